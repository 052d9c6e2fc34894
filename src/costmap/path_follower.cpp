#include "rigdesign/costmap/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigdesign::costmap {

VelocityCommand pursue(const std::vector<model::Vec2>& path_world, const Pose2& pose,
                       const FollowerParams& params) {
  if (path_world.empty()) return {};
  std::size_t nearest = 0;
  for (std::size_t i = 1; i < path_world.size(); ++i) {
    if ((path_world[i] - pose.position).squaredNorm() <
        (path_world[nearest] - pose.position).squaredNorm()) {
      nearest = i;
    }
  }
  std::size_t target = path_world.size() - 1;
  for (std::size_t i = nearest; i < path_world.size(); ++i) {
    if ((path_world[i] - pose.position).norm() >= params.lookahead) {
      target = i;
      break;
    }
  }
  const model::Vec2 offset = path_world[target] - pose.position;
  const double distance = offset.norm();
  if (distance < 1e-9) return {};
  const double alpha =
      std::remainder(std::atan2(offset.y(), offset.x()) - pose.yaw, 2.0 * std::numbers::pi);
  VelocityCommand command;
  if (std::abs(alpha) > params.turn_in_place_angle) {
    command.angular = std::copysign(params.max_angular_speed, alpha);
    return command;
  }
  const double curvature = 2.0 * std::sin(alpha) / distance;  // pure pursuit
  command.linear = params.speed;
  if (std::abs(curvature * command.linear) > params.max_angular_speed) {
    command.linear = params.max_angular_speed / std::abs(curvature);
  }
  command.angular = curvature * command.linear;
  return command;
}

Pose2 integrate_unicycle(const Pose2& pose, const VelocityCommand& command, double dt) {
  Pose2 next = pose;
  const double turn = command.angular * dt;
  if (std::abs(turn) < 1e-9) {
    next.position += command.linear * dt * model::Vec2(std::cos(pose.yaw), std::sin(pose.yaw));
  } else {
    const double radius = command.linear / command.angular;
    next.position += radius * model::Vec2(std::sin(pose.yaw + turn) - std::sin(pose.yaw),
                                          -std::cos(pose.yaw + turn) + std::cos(pose.yaw));
  }
  next.yaw = std::remainder(pose.yaw + turn, 2.0 * std::numbers::pi);
  return next;
}

}  // namespace rigdesign::costmap
