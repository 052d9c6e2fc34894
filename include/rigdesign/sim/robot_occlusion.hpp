#pragma once
/// What a sensor's own robot hides from it in a simulation (issue 52 item 2a): the body, the
/// description's collision parts (all but the sensor's own housing link), the other mounts'
/// housings and the rig's supports, by the rules the coverage engine uses (geometry::MountedFov),
/// so that a simulated sensor and the coverage report agree about what the robot hides.
#include <vector>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::sim {

/// For each ray (sensor frame, as ray_pattern gives them) the distance [m] from the sensor
/// origin at which the robot hides the rest of it; +infinity where nothing of the robot is in
/// its way. `mode` bounds the search at its max range.
std::vector<double> robot_free_ranges(const model::Rig& rig, const model::SensorLibrary& library,
                                      const model::Mount& mount, const model::SensorMode& mode,
                                      const std::vector<model::Vec3>& rays);

}  // namespace rigdesign::sim
