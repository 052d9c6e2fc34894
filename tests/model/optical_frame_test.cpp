#include "rigdesign/model/optical_frame.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/model/point_cloud.hpp"
#include "rigdesign/model/rotation.hpp"

using namespace rigdesign;

TEST_CASE("the optical frame looks along the sensor's x axis (REP-103)", "[model]") {
  const model::Pose3 T = model::T_sensor_optical();
  // z forward, x right, y down in the optical frame; x forward, y left, z up in the sensor's.
  CHECK((T * model::Vec3::UnitZ() - model::Vec3::UnitX()).norm() < 1e-15);
  CHECK((T * model::Vec3::UnitX() + model::Vec3::UnitY()).norm() < 1e-15);
  CHECK((T * model::Vec3::UnitY() + model::Vec3::UnitZ()).norm() < 1e-15);
  CHECK(T.translation().norm() == 0.0);
  CHECK(T.linear().determinant() == Approx(1.0));
  // ROS's static transform for an optical frame: rpy = (-pi/2, 0, -pi/2).
  const model::Mat3 ros = model::rotation_from_rpy(-M_PI / 2, 0.0, -M_PI / 2);
  CHECK((ros - T.linear()).norm() < 1e-12);
}

TEST_CASE("transform_cloud maps points and puts the sensor at the transform's origin", "[model]") {
  model::PointCloud cloud;
  cloud.points = {{1.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.5f}};
  // A quarter turn left about z, then 1 m up.
  model::Pose3 T_robot_cloud = model::pose_from_xyz_rpy({0.0, 0.0, 1.0}, {0.0, 0.0, M_PI / 2});
  const model::PointCloud moved = model::transform_cloud(cloud, T_robot_cloud);
  REQUIRE(moved.size() == 2);
  CHECK((moved.points[0] - model::Point3f(0.0f, 1.0f, 1.0f)).norm() < 1e-6f);
  CHECK((moved.points[1] - model::Point3f(-2.0f, 0.0f, 1.5f)).norm() < 1e-6f);
  CHECK((moved.origin - model::Point3f(0.0f, 0.0f, 1.0f)).norm() < 1e-6f);
}
