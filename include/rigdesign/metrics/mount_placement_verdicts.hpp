#pragma once
/// B1, a rig a technician can build (issue 52 item 1): every mount's data origin is outside
/// the robot body but for the sensor's own housing (geometry/mount_placement.hpp). Judged for
/// every rig, with or without requirements: a buried sensor sees nothing through the part
/// that holds it, whatever was asked of it.
#include <vector>

#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::metrics {

/// One B1 verdict per mount, at the mount's pose: fails naming the link and its <collision>
/// element in the description (or the rig's `body`).
std::vector<RequirementResult> placement_verdicts(const model::Rig& rig);

/// The same findings as warnings at each buried mount's pose, for the commands that compute
/// with the rig rather than judge it (coverage, metrics, report, export, the simulations).
std::vector<model::Diagnostic> placement_warnings(const model::Rig& rig);

}  // namespace rigdesign::metrics
