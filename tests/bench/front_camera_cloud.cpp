#include "front_camera_cloud.hpp"

#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::bench {

model::PointCloud as_front_camera(const model::PointCloud& optical) {
  model::Pose3 body_from_optical = model::Pose3::Identity();
  body_from_optical.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const model::Pose3 T_robot_sensor = model::pose_from_xyz_rpy(
      model::Vec3(0.46, 0, 0.75), model::Vec3(0, model::deg_to_rad(25), 0));
  const Eigen::Isometry3f T = (T_robot_sensor * body_from_optical).cast<float>();
  model::PointCloud moved;
  for (const model::Point3f& p : optical.points) moved.points.push_back(T * p);
  moved.origin = T.translation();
  return moved;
}

}  // namespace rigdesign::bench
