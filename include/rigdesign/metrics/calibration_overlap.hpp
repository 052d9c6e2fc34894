#pragma once
/// R9, calibration overlap (issue 38, item 3): target-free extrinsic calibration registers
/// structure two sensors both see, so every pair whose shared columns (column_area of
/// metrics/covisibility.hpp: an upright target standing there is seen by both) reach the
/// requirement's min_overlap is an edge of a graph over the mounts; the rig passes when that graph
/// is connected (every sensor calibrated to every other through a chain of pairs) or, with `pairs:
/// all`, complete. A failure names the sensors cut off.
#include <vector>

#include "rigdesign/metrics/covisibility.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/requirements.hpp"

namespace rigdesign::metrics {

/// The graph's connected components, each a sorted list of mount indices, the largest first
/// (ties: the one with the smallest index first).
std::vector<std::vector<std::size_t>> overlap_components(const Covisibility& overlap,
                                                         double min_overlap);

RequirementResult calibration_verdict(const model::Rig& rig,
                                      const model::CalibrationRequirement& required,
                                      const Covisibility& overlap);

}  // namespace rigdesign::metrics
