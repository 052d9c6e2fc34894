#pragma once
// The motions a scene file gives its moving objects, as pose functions of time for
// MovingObject::T_world_object. Private to io (scene files are their only source).
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::io {

struct Waypoint {
  double t = 0.0;                         ///< [s]
  model::Vec3 xyz = model::Vec3::Zero();  ///< object origin in the world frame [m]
  double yaw = 0.0;                       ///< heading about +z [rad]
};

/// Piecewise-linear motion through waypoints (precondition: at least one, times strictly
/// increasing). Position is interpolated linearly, yaw along the shorter arc (a half turn
/// exactly goes counter-clockwise). Outside [t_first, t_last] the pose is clamped to the end
/// waypoints, or with `loop` the motion repeats with period t_last - t_first (jumping from
/// the last waypoint back to the first: repeat the first position at the end for a closed
/// path).
struct WaypointPath {
  std::vector<Waypoint> waypoints;
  bool loop = false;

  model::Pose3 operator()(double t) const;
};

/// Counter-clockwise walk around an axis-aligned ellipse on the floor (z = 0), starting at
/// (centre.x + a, centre.y) at t = 0: angle 2 pi t / period. With `face_travel` the object's
/// x axis points along the direction of travel, otherwise it keeps yaw 0.
struct EllipsePath {
  model::Vec2 centre = model::Vec2::Zero();  ///< [m]
  model::Vec2 semi_axes{1.0, 1.0};           ///< a along x, b along y [m], > 0
  double period = 1.0;                       ///< one lap [s], > 0
  bool face_travel = true;

  model::Pose3 operator()(double t) const;
};

}  // namespace rigdesign::io
