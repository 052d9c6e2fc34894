#include "rigdesign/model/rotation.hpp"

namespace rigdesign {

Mat3 rotation_from_rpy(double roll, double pitch, double yaw) {
  const Eigen::AngleAxisd about_x(roll, Vec3::UnitX());
  const Eigen::AngleAxisd about_y(pitch, Vec3::UnitY());
  const Eigen::AngleAxisd about_z(yaw, Vec3::UnitZ());
  return (about_z * about_y * about_x).toRotationMatrix();
}

Pose3 pose_from_xyz_rpy(const Vec3& xyz, const Vec3& rpy) {
  Pose3 pose = Pose3::Identity();
  pose.linear() = rotation_from_rpy(rpy.x(), rpy.y(), rpy.z());
  pose.translation() = xyz;
  return pose;
}

}  // namespace rigdesign
