#pragma once
/// What a coverage run finds that the numbers alone hide, as warnings that name the mount:
/// a mount that sees none of the area to perceive (a lidar above the area's top, a camera
/// looking the wrong way), saying whether it still sets F, R or N for the whole rig.
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::metrics {

std::vector<model::Diagnostic> coverage_findings(const model::Rig& rig,
                                                 const ResultantMetrics& resultant,
                                                 const RigCoverage& coverage);

}  // namespace rigdesign::metrics
