#pragma once
/// A pure-pursuit path follower for a differential-drive robot (issue 6 item 2): it steers
/// towards the path point one lookahead distance ahead at a set speed, and turns on the spot
/// when that point lies far to the side or behind.
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::costmap {

/// A planar pose: position [m] and heading [rad] about +z, world frame.
struct Pose2 {
  model::Vec2 position = model::Vec2::Zero();
  double yaw = 0.0;
};

struct FollowerParams {
  double speed = 0.4;              ///< [m/s] forward speed while driving
  double max_angular_speed = 1.0;  ///< [rad/s]
  double lookahead = 0.6;          ///< [m] distance to the pursued path point
  /// [rad] a pursued point farther off the heading than this turns the robot on the spot.
  double turn_in_place_angle = 1.0;
};

/// Linear [m/s] and angular [rad/s] velocity.
struct VelocityCommand {
  double linear = 0.0;
  double angular = 0.0;
  bool is_zero() const { return linear == 0.0 && angular == 0.0; }
};

/// The command that pursues `path_world` (waypoints from the robot's cell to the goal) from
/// `pose`: the first waypoint after the nearest one that lies at least `lookahead` away (else
/// the last), curvature 2 sin(alpha) / distance, speed reduced so the angular speed stays
/// within its limit. An empty path gives a zero command.
VelocityCommand pursue(const std::vector<model::Vec2>& path_world, const Pose2& pose,
                       const FollowerParams& params);

/// Moves a unicycle for `dt` [s] under a constant command (exact arc).
Pose2 integrate_unicycle(const Pose2& pose, const VelocityCommand& command, double dt);

}  // namespace rigdesign::costmap
