#include "rigdesign/model/rotation.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::model {

Mat3 rotation_from_rpy(double roll, double pitch, double yaw) {
  const Eigen::AngleAxisd about_x(roll, Vec3::UnitX());
  const Eigen::AngleAxisd about_y(pitch, Vec3::UnitY());
  const Eigen::AngleAxisd about_z(yaw, Vec3::UnitZ());
  return (about_z * about_y * about_x).toRotationMatrix();
}

Vec3 rpy_from_rotation(const Mat3& rotation) {
  // R = Rz(yaw) Ry(pitch) Rx(roll): R(2,0) = -sin(pitch), R(2,1) / R(2,2) = tan(roll),
  // R(1,0) / R(0,0) = tan(yaw). At pitch = +-90 deg only roll - yaw (or roll + yaw) is
  // defined; roll is set to 0 there.
  const double pitch = std::asin(std::clamp(-rotation(2, 0), -1.0, 1.0));
  if (std::abs(rotation(2, 0)) > 1.0 - 1e-12) {
    return {0.0, pitch, std::atan2(-rotation(0, 1), rotation(1, 1))};
  }
  return {std::atan2(rotation(2, 1), rotation(2, 2)), pitch,
          std::atan2(rotation(1, 0), rotation(0, 0))};
}

Pose3 pose_from_xyz_rpy(const Vec3& xyz, const Vec3& rpy) {
  Pose3 pose = Pose3::Identity();
  pose.linear() = rotation_from_rpy(rpy.x(), rpy.y(), rpy.z());
  pose.translation() = xyz;
  return pose;
}

}  // namespace rigdesign::model
