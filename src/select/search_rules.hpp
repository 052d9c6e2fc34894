#pragma once
// Rules the branch and bound and the brute force share, so that both answer the same
// question: when a share meets a threshold, and which of two feasible rigs wins.
#include <algorithm>
#include <limits>
#include <vector>

#include "rigdesign/select/search.hpp"

namespace rigdesign::select {

inline bool meets(double share, double threshold) {
  return share >= threshold - kThresholdSlack;
}

/// Whether a feasible rig of `cost` and per-sector `margins` (smallest first) beats the best
/// so far: cheaper, or as cheap with margins larger compared smallest first (leximin: the
/// smallest margin decides, then the next smallest). Counts the ties at the best cost.
inline bool improves(SearchResult& best, double cost, const std::vector<double>& margins) {
  if (!best.found || cost < best.cost.total - kCostTie) {
    best.ties = 1;
    return true;
  }
  if (cost > best.cost.total + kCostTie) return false;
  ++best.ties;
  return std::lexicographical_compare(best.margins.begin(), best.margins.end(), margins.begin(),
                                      margins.end());
}

/// The smallest of per-sector margins sorted smallest first (+infinity without sectors).
inline double smallest_of(const std::vector<double>& margins) {
  return margins.empty() ? std::numeric_limits<double>::infinity() : margins.front();
}

}  // namespace rigdesign::select
