#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::model {

PointCloud transform_cloud(const PointCloud& cloud, const Pose3& T_target_cloud) {
  PointCloud moved;
  moved.points.reserve(cloud.size());
  const Eigen::Isometry3f transform = T_target_cloud.cast<float>();
  for (const Point3f& p : cloud.points) moved.points.push_back(transform * p);
  moved.origin = T_target_cloud.translation().cast<float>();
  return moved;
}

}  // namespace rigdesign::model
