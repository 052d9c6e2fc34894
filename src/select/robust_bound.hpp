#pragma once
// What a rig that must survive failures (issue 15's robustness, issue 32's speed) adds to the
// branch and bound's pruning. Both rules are necessary conditions, so the search stays exact:
// - Coverage: a rig survives the failure of slot j only if everything except j's sensor
//   meets the after-failure thresholds. For a slot still undecided at a node that bounds as
//   the chosen sensors plus every option of the other undecided slots; if even that misses
//   an after-failure threshold, no completion survives (choosing j, its failure leaves too
//   little; not choosing it, the rig is no more than that, and any failure leaves less).
// - Price: under n-1, an angle whose after-failure threshold asks for anything needs two
//   chosen sensors covering something there (one alone leaves nothing when it fails); under
//   a condition, one that survives the condition. A node with fewer must still buy such
//   options of distinct undecided slots: at least their least price, bandwidth and load.
#include <cstdint>
#include <vector>

#include "rigdesign/select/class_coverage.hpp"
#include "rigdesign/select/search.hpp"
#include "select/sector_needs.hpp"

namespace rigdesign::select {

class RobustBound {
 public:
  /// `order`: the options the search tries per slot (the undominated ones).
  RobustBound(const SearchProblem& problem, const ClassCoverage& classes, std::vector<Need> needs,
              const std::vector<std::vector<int>>& order);

  /// The needs after a failure (the robustness sectors at their angles).
  const std::vector<Need>& needs() const { return needs_; }

  /// Option `option` of `slot` joins (leaves) the node's chosen sensors.
  void add(std::size_t slot, int option);
  void remove(std::size_t slot, int option);

  /// Whether every undecided slot's failure may still be survived by some completion of a
  /// node at `depth` whose chosen sensors cover `chosen` (bits) and `counts` (per angle).
  bool may_survive(std::size_t depth, const std::uint64_t* chosen,
                   const std::vector<CellCounts>& counts) const;

  /// The least price, bandwidth and CPU load any surviving completion of a node at `depth`
  /// still adds, part by part (not possible(): none exists).
  LeastAddition least_addition(std::size_t depth) const;

  /// Each need still short of covering sensors, with the least a surviving completion of a
  /// node at `depth` adds for it.
  void append_unmet(std::size_t depth, std::vector<UnmetNeed>& unmet) const;

 private:
  // One of an option's covers at a need's angle: anything of the cells, of the floor.
  struct Touch {
    std::size_t need = 0;
    bool cells = false;
    bool floor = false;
  };
  // The least options of slots >= depth covering something at a need's angle add.
  struct Cheapest {
    LeastAddition one = LeastAddition::none();        // any option
    LeastAddition two = LeastAddition::none();        // two options of distinct slots
    LeastAddition surviving = LeastAddition::none();  // one that survives the condition
  };
  LeastAddition extra_for(std::int64_t needed, int coverers, int surviving,
                          const Cheapest& cheapest) const;
  // What need i still asks a completion of a node at `depth` to add, cells and floor.
  LeastAddition need_extra(std::size_t depth, std::size_t i) const;

  const SearchProblem& problem_;
  const ClassCoverage& classes_;
  std::vector<Need> needs_;
  std::vector<std::vector<std::vector<Touch>>> touches_;  // [slot][option]
  std::vector<std::vector<std::size_t>> slot_needs_;      // [slot]: needs its options touch
  std::vector<std::vector<Cheapest>> cheapest_cells_;     // [depth][need]
  std::vector<std::vector<Cheapest>> cheapest_floor_;     // [depth][need]
  // [depth][slot >= depth]: the union of every option of slots >= depth except that slot's,
  // and its counts per need (n-1 only).
  std::vector<std::vector<std::vector<std::uint64_t>>> rest_without_;
  std::vector<std::vector<std::vector<CellCounts>>> rest_without_counts_;
  // Chosen sensors covering something at each need's angle: all, and those surviving.
  std::vector<int> coverers_cells_, coverers_floor_, surviving_cells_, surviving_floor_;
};

}  // namespace rigdesign::select
