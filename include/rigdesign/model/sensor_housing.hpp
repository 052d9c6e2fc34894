#pragma once
/// Which of a robot description's links is a sensor's own housing (issue 52 item 1): the only
/// collision geometry that sensor may see through. It is read from the description's link
/// tree, never inferred from a part merely holding the sensor: going up from the link the
/// sensor's pose names, the first link with collision geometry, provided that link is the
/// sensor's alone. A link on the way from the robot frame up to the description's root (the
/// Jackal's base_link), or one that carries other collision geometry below it (its chassis
/// with the wheels), is the robot's, not a sensor's. The TurtleBot 4's oakd_link above
/// oakd_rgb_camera_frame and a VLP-16's base cylinder above its data frame are housings.
#include <string>

#include "rigdesign/model/rig.hpp"

namespace rigdesign::model {

/// The housing link of a sensor whose pose is the description link `urdf_link`; empty for a
/// pose given as numbers or when the rule above finds none.
std::string housing_link(const DescribedRobot& robot, const std::string& urdf_link);

/// Why `link` cannot be a sensor's housing by the rule above (a pose given as numbers may
/// state its housing: `pose: {xyz, rpy_deg, housing: oakd_link}`, as the studio saves a sensor
/// it moved out of a description link); empty when it can.
std::string housing_refusal(const DescribedRobot& robot, const std::string& link);

}  // namespace rigdesign::model
