#pragma once
/// A point cloud as the filters and the simulator share it: float positions (as PCL and
/// sensor drivers deliver them) in one frame, with the sensor origin in that frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

using Point3f = Eigen::Vector3f;

struct PointCloud {
  std::vector<Point3f> points;  ///< [m]
  /// Sensor origin and orientation in the cloud's frame (PCD's VIEWPOINT).
  Point3f origin = Point3f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();

  std::size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
};

/// The cloud's points mapped by `T_target_cloud` into the target frame. The cloud is taken as
/// recorded at its sensor, so the sensor origin becomes T_target_cloud's translation.
PointCloud transform_cloud(const PointCloud& cloud, const Pose3& T_target_cloud);

}  // namespace rigdesign::model
