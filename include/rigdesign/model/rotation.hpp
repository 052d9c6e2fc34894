#pragma once
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// Rotation from roll, pitch, yaw [rad] about the fixed x, y, z axes, applied in that order:
/// R = Rz(yaw) * Ry(pitch) * Rx(roll). This is URDF's and ROS's `rpy` convention, so a pose
/// copied from a robot description means the same here.
Mat3 rotation_from_rpy(double roll, double pitch, double yaw);

/// Roll, pitch, yaw [rad] of a rotation, in the convention above; pitch in [-pi/2, pi/2].
Vec3 rpy_from_rotation(const Mat3& rotation);

/// The same pose from xyz [m] and rpy [rad].
Pose3 pose_from_xyz_rpy(const Vec3& xyz, const Vec3& rpy);

}  // namespace rigdesign::model
