#pragma once
/// A rig a technician can build (issue 52): B1, every mount's data origin is outside the robot
/// body but for the sensor's own housing (geometry/mount_placement.hpp); B2, every sensor's
/// datasheet housing cuts into neither the body nor another sensor's housing
/// (geometry/housing_clearance.hpp). Judged for every rig, with or without requirements: a
/// buried sensor sees nothing through the part that holds it, and two solids cannot share space.
#include <vector>

#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

/// One B1 verdict per mount, then one B2 verdict per mount whose sensor has a housing, each at
/// the mount's pose: B1 fails naming the link and its <collision> element in the description
/// (or the rig's `body`); B2 names what the housing cuts into and how deep.
std::vector<RequirementResult> placement_verdicts(const model::Rig& rig,
                                                  const model::SensorLibrary& library);

/// Issue 52 item 3: a warning at each mount whose housing touches nothing that could hold it
/// (the body, a description link, another housing), with the gap in millimetres
/// (geometry::housing_gap).
std::vector<model::Diagnostic> floating_warnings(const model::Rig& rig,
                                                 const model::SensorLibrary& library);

/// The floating warnings, then the failures above as warnings at each failing mount's pose, for the
/// commands that compute with the rig rather than judge it (coverage, metrics, report, export, the
/// simulations).
std::vector<model::Diagnostic> placement_warnings(const model::Rig& rig,
                                                  const model::SensorLibrary& library);

}  // namespace rigdesign::metrics
