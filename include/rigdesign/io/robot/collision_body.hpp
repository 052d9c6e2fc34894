#pragma once
/// The robot body as a description's collision geometry: every <collision> of every link,
/// placed with the joints at zero and expressed in the robot frame (`base_link`, on the
/// floor under the robot's centre: REP-105's base_footprint). Boxes and meshes become
/// triangles exactly; cylinders whose axis is vertical stay round (exact shadows); tilted
/// cylinders and spheres are tessellated, and each part records its largest distance from
/// the true surface. This is reading: the collision elements put in the robot frame as the
/// model's body; loaders make no geometric test with it (containment, occlusion).
#include <string>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/robot_description.hpp"

namespace rigdesign::io {

/// Sides of a tessellated cylinder (and of a sphere's bands). The polygon is circumscribed,
/// so the mesh holds the true solid and lies at most r (1 / cos(pi / 48) - 1) = 0.21 % of
/// the radius outside it.
inline constexpr int kRoundSides = 48;

/// Precondition: `base_link` is a link of `description`; the robot frame is that link moved
/// down by `base_height` (a base link above the floor, as on the Jackal). The body's height is
/// the parts' highest point, its radius their farthest horizontal distance from the axis.
model::RobotBody body_from_description(const model::RobotDescription& description,
                                       const std::string& base_link, double base_height = 0.0);

}  // namespace rigdesign::io
