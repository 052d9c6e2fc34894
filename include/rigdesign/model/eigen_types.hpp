#pragma once
/// The project's one Eigen alias header (STYLE.md rule 6): fixed-size types at module
/// boundaries, Isometry3d for poses whose frames are named `T_<to>_<from>`.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace rigdesign::model {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Pose3 = Eigen::Isometry3d;

}  // namespace rigdesign::model
