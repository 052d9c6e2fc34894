// Issue 52 item 4: the root frame the export places, composed with the static transforms the
// sensor's own driver broadcasts (recorded hop by hop from the drivers' sources in
// data/ros_drivers/driver_transforms.yaml, read here independently of sensors.yaml), lands on
// the designed data frame to 1e-6 m and 1e-6 rad, for every bundled sensor whose driver
// broadcasts its frames. The joint is read from the exported xacro's text.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "rigdesign/deploy/ros/description/sensors_xacro_writer.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;

namespace {

// URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll), written out here.
model::Pose3 urdf_pose(const model::Vec3& xyz, const model::Vec3& rpy) {
  model::Pose3 pose = model::Pose3::Identity();
  pose.linear() = (Eigen::AngleAxisd(rpy.z(), model::Vec3::UnitZ()) *
                   Eigen::AngleAxisd(rpy.y(), model::Vec3::UnitY()) *
                   Eigen::AngleAxisd(rpy.x(), model::Vec3::UnitX()))
                      .toRotationMatrix();
  pose.translation() = xyz;
  return pose;
}

model::Vec3 triple(const YAML::Node& node) {
  return {node[0].as<double>(), node[1].as<double>(), node[2].as<double>()};
}

model::Vec3 triple(const std::string& text) {
  std::istringstream in(text);
  model::Vec3 v;
  in >> v.x() >> v.y() >> v.z();
  return v;
}

// REP-103: an optical frame's z is the body frame's x, its x the body's -y, its y the body's -z.
model::Pose3 body_to_optical() {
  model::Pose3 pose = model::Pose3::Identity();
  pose.linear().col(0) = -model::Vec3::UnitY();
  pose.linear().col(1) = -model::Vec3::UnitZ();
  pose.linear().col(2) = model::Vec3::UnitX();
  return pose;
}

// The text of attribute `name` in the first element at or after `from`.
std::string attribute(const std::string& xml, std::size_t from, const std::string& name) {
  const std::size_t start = xml.find(name + "=\"", from);
  REQUIRE(start != std::string::npos);
  const std::size_t value = start + name.size() + 2;
  return xml.substr(value, xml.find('"', value) - value);
}

// The origin of the exported joint whose child is `link`, from the xacro's text.
model::Pose3 joint_to(const std::string& xacro, const std::string& link) {
  const std::size_t child = xacro.find("<child link=\"${prefix}" + link + "\"/>");
  REQUIRE(child != std::string::npos);
  const std::size_t origin = xacro.find("<origin ", child);
  REQUIRE(origin != std::string::npos);
  return urdf_pose(triple(attribute(xacro, origin, "xyz")),
                   triple(attribute(xacro, origin, "rpy")));
}

}  // namespace

TEST_CASE("every driver's own transforms take the exported root to the designed data frame") {
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  const YAML::Node research =
      YAML::LoadFile(test::source_path("data/ros_drivers/driver_transforms.yaml"));
  REQUIRE(research.size() >= 18);
  // A pose with every axis turned, off every axis, on a cylinder body.
  const model::Pose3 T_robot_sensor =
      urdf_pose(model::Vec3(0.21, -0.13, 0.64), model::Vec3(0.05, 0.3, -0.4));
  for (const YAML::Node& entry : research) {
    const std::string sensor_id = entry["sensor"].as<std::string>();
    INFO(sensor_id);
    const model::Sensor* sensor = library.find(sensor_id);
    REQUIRE(sensor != nullptr);
    REQUIRE(sensor->ros2);
    CHECK(sensor->ros2->driver_frames.front() == entry["root"].as<std::string>());
    CHECK(sensor->ros2->frame_id == entry["data_frame"].as<std::string>());
    model::Rig rig;
    rig.body.radius = 0.3;
    rig.body.height = 0.5;
    rig.distance_of_interest = 2.0;
    model::Mount mount;
    mount.id = "cam";
    mount.sensor_id = sensor_id;
    mount.mode_id = sensor->modes.front().id;
    mount.T_robot_sensor = T_robot_sensor;
    rig.mounts.push_back(mount);
    const std::string xacro =
        deploy::sensors_xacro_text(deploy::sensor_frames(rig, library), "driver frames test");
    model::Pose3 T_robot_data = joint_to(xacro, entry["root"].as<std::string>());
    for (const YAML::Node& hop : entry["hops"])
      T_robot_data = T_robot_data * urdf_pose(triple(hop["xyz"]), triple(hop["rpy"]));
    const bool optical = entry["data_axes"].as<std::string>() == "optical";
    const model::Pose3 designed = optical ? T_robot_sensor * body_to_optical() : T_robot_sensor;
    CHECK((T_robot_data.translation() - designed.translation()).norm() < 1e-6);
    CHECK(Eigen::AngleAxisd(T_robot_data.linear().transpose() * designed.linear()).angle() < 1e-6);
  }
}
