#include "io/scene/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigdesign::io {
namespace {

model::Pose3 yawed_pose(const model::Vec3& xyz, double yaw) {
  model::Pose3 T_world_object = model::Pose3::Identity();
  T_world_object.linear() = Eigen::AngleAxisd(yaw, model::Vec3::UnitZ()).toRotationMatrix();
  T_world_object.translation() = xyz;
  return T_world_object;
}

// `angle` wrapped into (-pi, pi]: the signed shorter turn.
double shorter_turn(double angle) {
  const double two_pi = 2 * std::numbers::pi;
  double wrapped = std::fmod(angle, two_pi);
  if (wrapped > std::numbers::pi) wrapped -= two_pi;
  if (wrapped <= -std::numbers::pi) wrapped += two_pi;
  return wrapped;
}

}  // namespace

model::Pose3 WaypointPath::operator()(double t) const {
  const Waypoint& first = waypoints.front();
  const Waypoint& last = waypoints.back();
  const double span = last.t - first.t;
  if (loop && span > 0) {
    double into = std::fmod(t - first.t, span);
    if (into < 0) into += span;
    t = first.t + into;
  }
  if (t <= first.t) return yawed_pose(first.xyz, first.yaw);
  if (t >= last.t) return yawed_pose(last.xyz, last.yaw);
  // The segment whose end comes after t (there is one: first.t < t < last.t).
  const auto end = std::upper_bound(waypoints.begin(), waypoints.end(), t,
                                    [](double time, const Waypoint& w) { return time < w.t; });
  const Waypoint& a = *(end - 1);
  const Waypoint& b = *end;
  const double s = (t - a.t) / (b.t - a.t);
  return yawed_pose(a.xyz + s * (b.xyz - a.xyz), a.yaw + s * shorter_turn(b.yaw - a.yaw));
}

model::Pose3 EllipsePath::operator()(double t) const {
  const double angle = 2 * std::numbers::pi * t / period;
  const double a = semi_axes.x();
  const double b = semi_axes.y();
  const model::Vec3 xyz(centre.x() + a * std::cos(angle), centre.y() + b * std::sin(angle), 0.0);
  // The tangent d/d(angle) (a cos, b sin) = (-a sin, b cos).
  const double heading = face_travel ? std::atan2(b * std::cos(angle), -a * std::sin(angle)) : 0.0;
  return yawed_pose(xyz, heading);
}

}  // namespace rigdesign::io
