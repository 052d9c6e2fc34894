// Issues 14 and 30: the rig's description plus the exported sensors.urdf.xacro, expanded by
// the built-in xacro expander and parsed by urdfdom, is one URDF with every mount's frame to
// 1e-9 m / 1e-9 rad; and
// the exported nav2 file, read back by rigdesign's own nav2 reader, gives the same sources.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/ros/description/sensors_xacro_writer.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// The driver's recorded static transforms from its root to its data frame, and whether that
// frame is optical (data/ros_drivers/driver_transforms.yaml, read with yaml-cpp).
YAML::Node driver_hops(const std::string& sensor_id, bool& optical) {
  for (const YAML::Node& entry :
       YAML::LoadFile(source_path("data/ros_drivers/driver_transforms.yaml"))) {
    if (entry["sensor"].as<std::string>() != sensor_id) continue;
    optical = entry["data_axes"].as<std::string>() == "optical";
    return entry["hops"];
  }
  FAIL("no driver transforms recorded for " << sensor_id);
  return {};
}

// One hop: URDF's xyz and fixed-axis roll, pitch, yaw (R = Rz Ry Rx).
model::Pose3 hop_pose(const YAML::Node& hop) {
  model::Pose3 pose = model::Pose3::Identity();
  pose.linear() = (Eigen::AngleAxisd(hop["rpy"][2].as<double>(), model::Vec3::UnitZ()) *
                   Eigen::AngleAxisd(hop["rpy"][1].as<double>(), model::Vec3::UnitY()) *
                   Eigen::AngleAxisd(hop["rpy"][0].as<double>(), model::Vec3::UnitX()))
                      .toRotationMatrix();
  pose.translation() = model::Vec3(hop["xyz"][0].as<double>(), hop["xyz"][1].as<double>(),
                                   hop["xyz"][2].as<double>());
  return pose;
}

double rotation_error(const model::Pose3& a, const model::Pose3& b) {
  const Eigen::AngleAxisd difference(a.linear().transpose() * b.linear());
  return std::abs(difference.angle());
}

// The rig's own description (or, without one, just the parent link) with the exported macro
// included after it: what a robot team's top-level xacro does.
std::string wrapper_text(const model::Rig& rig, const std::string& parent) {
  std::string text =
      "<?xml version=\"1.0\"?>\n<robot name=\"wrapper\" "
      "xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";
  if (rig.robot) {
    text += "  <xacro:include filename=\"" +
            std::filesystem::absolute(rig.robot->description).string() + "\"/>\n";
  } else {
    text += "  <link name=\"" + parent + "\"/>\n";
  }
  return text +
         "  <xacro:include filename=\"sensors.urdf.xacro\"/>\n  <xacro:rig_sensors/>\n</robot>\n";
}

}  // namespace

// Issue 30 item 4: description + exported macro -> one URDF that urdfdom accepts (it refuses
// a link or joint name given twice), with every mount's data frame where the rig says.
TEST_CASE("export: every bundled rig's description plus its sensors.urdf.xacro is one URDF",
          "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  for (const std::string name : {"ur_cleaner", "ur_cleaner_from_urdf", "delivery_amr", "elektron",
                                 "cell", "cart_two_scanners", "turtlebot4", "jackal"}) {
    INFO(name);
    const model::Rig rig = io::load_rig(source_path("rigs/" + name + ".yaml"));
    const deploy::SensorFrames frames = deploy::sensor_frames(rig, library);
    TempFolder folder;
    folder.write("sensors.urdf.xacro", deploy::sensors_xacro_text(frames, "round trip of " + name));
    io::RobotDescriptionRequest request;
    request.path = folder.write("wrapper.urdf.xacro", wrapper_text(rig, frames.parent));
    request.expander = io::RobotDescriptionRequest::Expander::builtin;
    request.load_meshes = false;
    if (rig.robot) {
      request.args = rig.robot->args;
      request.environment = rig.robot->environment;
      request.package_paths = rig.robot->package_paths;
    }
    const model::RobotDescription combined = io::load_robot_description(request);
    // Every description link is still there, once (urdfdom refuses duplicates), and every
    // mount's data frame stands where the rig puts the sensor.
    for (const auto& [link, pose] : rig.link_poses) CHECK(combined.T_root_link.count(link) == 1);
    for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
      const model::Mount& mount = rig.mounts[i];
      const deploy::SensorFrame& frame = frames.frames[i];
      INFO(mount.id << " in " << frame.data_frame);
      if (!mount.urdf_link.empty()) CHECK(frame.link == mount.urdf_link);
      // A frame the driver broadcasts itself (realsense's camera_depth_optical_frame) is not
      // the URDF's: the URDF gives its root, the link, and the driver's own transforms
      // (recorded hop by hop in data/ros_drivers/driver_transforms.yaml) take it there.
      const std::string& named = frame.data_frame_from_driver ? frame.link : frame.data_frame;
      if (frame.data_frame_from_driver) CHECK(combined.T_root_link.count(frame.data_frame) == 0);
      const std::optional<model::Pose3> found = combined.T_base(frames.parent, named);
      REQUIRE(found);
      model::Pose3 T_robot_frame = *found;
      T_robot_frame.translation().z() += rig.base_link_height;
      bool optical = frame.optical_frame.has_value();
      if (frame.data_frame_from_driver) {
        const YAML::Node hops = driver_hops(mount.sensor_id, optical);
        for (const YAML::Node& hop : hops) T_robot_frame = T_robot_frame * hop_pose(hop);
      }
      const model::Pose3 expected =
          optical ? mount.T_robot_sensor * model::T_sensor_optical() : mount.T_robot_sensor;
      CHECK((T_robot_frame.translation() - expected.translation()).norm() < 1e-9);
      CHECK(rotation_error(T_robot_frame, expected) < 1e-9);
    }
  }
}

TEST_CASE(
    "export: a mount on a description link adds nothing; one beside it may not reuse "
    "its names",
    "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig jackal = io::load_rig(source_path("rigs/jackal.yaml"));
  const std::string text = deploy::sensors_xacro_text(deploy::sensor_frames(jackal, library), "t");
  // Both mounts sit on the accessories' own links (front_laser, velodyne): no link, no joint.
  CHECK(text.find("<link") == std::string::npos);
  CHECK(text.find("<joint") == std::string::npos);
  // The same laser placed by numbers under the accessory's name: the export would add
  // front_laser_joint, which the Jackal's accessory xacro already declares.
  model::Rig by_pose = jackal;
  by_pose.mounts[0].urdf_link.clear();
  REQUIRE(jackal.joint_where.count("front_laser_joint") == 1);
  const model::SourceLocation& declared = jackal.joint_where.at("front_laser_joint");
  CHECK_THROWS_WITH(deploy::sensor_frames(by_pose, library),
                    Catch::Contains("joint 'front_laser_joint'") &&
                        Catch::Contains(model::to_string(declared)) &&
                        Catch::Contains(model::to_string(jackal.mounts[0].where)));
}

TEST_CASE("export: a camera's optical frame is z forward, x right, y down", "[deploy]") {
  // REP-103 by hand: the optical frame's z axis is the body frame's x (forward), its x axis
  // the body's -y (right), its y axis the body's -z (down).
  const model::Mat3 R = model::T_sensor_optical().linear();
  CHECK((R.col(2) - model::Vec3::UnitX()).norm() < 1e-12);
  CHECK((R.col(0) + model::Vec3::UnitY()).norm() < 1e-12);
  CHECK((R.col(1) + model::Vec3::UnitZ()).norm() < 1e-12);
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path("rigs/ur_cleaner.yaml"));
  const std::string text = deploy::sensors_xacro_text(deploy::sensor_frames(rig, library), "t");
  // rpy of that rotation: roll -pi/2, pitch 0, yaw -pi/2 (the usual camera optical joint).
  CHECK(text.find("rpy=\"-1.5707963267948966 0 -1.5707963267948966\"") != std::string::npos);
  // The pico flexx has no ROS 2 driver (sensors.yaml ros2): its optical frame is the export's.
  CHECK(text.find("<child link=\"${prefix}left_camera_optical_frame\"/>") != std::string::npos);
  CHECK(text.find("top_lidar_optical_frame") == std::string::npos);
}

TEST_CASE("export: a parent that is no link of the rig is refused", "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path("rigs/turtlebot4.yaml"));
  CHECK_THROWS_WITH(deploy::sensor_frames(rig, library, "no_such_link"),
                    Catch::Contains("no link 'no_such_link'") && Catch::Contains("shell_link"));
  // Any link of the description may carry the sensors: the joint origin is then relative to it.
  const deploy::SensorFrames on_shell = deploy::sensor_frames(rig, library, "shell_link");
  const model::Pose3 T_robot_shell = rig.link_poses.at("shell_link");
  CHECK(((T_robot_shell * on_shell.frames[0].T_parent_link).translation() -
         rig.mounts[0].T_robot_sensor.translation())
            .norm() < 1e-12);
}
