#pragma once
// Rules the branch and bound and the brute force share, so that both answer the same
// question: when a share meets a threshold, and which of two feasible rigs wins.
#include "rigdesign/select/search.hpp"

namespace rigdesign::select {

inline bool meets(double share, double threshold) {
  return share >= threshold - kThresholdSlack;
}

/// Whether a feasible rig of `cost` and `margin` beats the best so far: cheaper, or as cheap
/// with a larger smallest margin. Counts the ties at the best cost.
inline bool improves(SearchResult& best, double cost, double margin) {
  if (!best.found || cost < best.cost.total - kCostTie) {
    best.ties = 1;
    return true;
  }
  if (cost > best.cost.total + kCostTie) return false;
  ++best.ties;
  return margin > best.margin;
}

}  // namespace rigdesign::select
