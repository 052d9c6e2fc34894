#pragma once
/// Triangle meshes of what the 3D view draws: a sensor mode's FOV volume and the robot body,
/// both in the robot frame (REP-103: x forward, y left, z up, origin on the floor under the
/// robot's centre).
#include <array>
#include <vector>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::render {

// The meshes built here are closed and wound counter-clockwise seen from outside, so
// (b - a) x (c - a) points out of the volume.

/// The closed surface of a mode's FOV volume placed on the robot by `T_robot_sensor`: every
/// point whose direction from the sensor origin is inside the FOV and whose distance from it
/// is in [mode.min_range, min(mode.max_range, truncate_at)] [m]. The two range limits are
/// spherical caps (the inner one shrinks to the sensor origin when min_range is 0) and the
/// FOV's boundary gives the side walls. Curved parts are tessellated with 48 segments over the
/// FOV's wider angle, which keeps the enclosed volume within about 1 % of the exact one.
/// Returns an empty mesh when the range interval is empty. Deterministic.
model::TriangleMesh fov_mesh(const model::SensorMode& mode, const model::Pose3& T_robot_sensor,
                             double truncate_at);

/// fov_mesh with what the body hides cut away: every vertex is pulled along its ray from the
/// sensor origin back to where the body first blocks it, so the volume is what the sensor
/// sees, as the coverage engine counts it (a lidar on a top plate loses the beams the plate
/// shadows). Tessellated at 2 deg at most, so the cut lands where it is.
model::TriangleMesh visible_fov_mesh(const model::SensorMode& mode,
                                     const model::Pose3& T_robot_sensor, double truncate_at,
                                     const geometry::BodyOccluder& body);

}  // namespace rigdesign::render
