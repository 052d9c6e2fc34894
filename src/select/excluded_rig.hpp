#pragma once
// Why a cheaper rig lost (issue 55 item 3): the cheapest rig meeting the coverage and sensor
// requirements when the catalog's CPU and transfer are free and unlimited, if it is cheaper
// than the rig `select` chose, and what the real CPUs and transfer make of it.
#include <atomic>
#include <future>
#include <optional>
#include <vector>

#include "rigdesign/select/selection.hpp"

namespace rigdesign::select {

/// The search for that rig, on its own thread beside the main search (both are
/// single-threaded; on two cores the answer costs no wall time unless it takes longer). It
/// takes the first cheapest rig in the search order: deterministic, with no tie-break.
class CheaperRigSearch {
 public:
  /// Starts searching `problem` (with any robustness) with free, unlimited hardware; the
  /// problem must outlive this object.
  explicit CheaperRigSearch(const SearchProblem& problem);
  CheaperRigSearch(const CheaperRigSearch&) = delete;
  CheaperRigSearch& operator=(const CheaperRigSearch&) = delete;
  /// Stops the search if it still runs, and waits for it.
  ~CheaperRigSearch();

  /// Waits for the search; the rig if its sensors cost less than `chosen.total`, with what
  /// the catalog's CPU and transfer make of it. `kept[k][i]` is the catalog option behind
  /// the problem's option i of slot k.
  std::optional<ExcludedRig> result(const std::vector<std::vector<const CatalogOption*>>& kept,
                                    const CostBreakdown& chosen);

 private:
  const SearchProblem& problem_;
  std::atomic<bool> stop_{false};
  std::future<std::optional<SearchResult>> search_;
};

}  // namespace rigdesign::select
