// Issue 14: the exported sensors.urdf.xacro, read back through the robot-description loader
// (the built-in xacro expander and urdfdom), gives every mount pose to 1e-9 m / 1e-9 rad; and
// the exported nav2 file, read back by rigdesign's own nav2 reader, gives the same sources.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/nav2/costmap_params_reader.hpp"
#include "rigdesign/io/robot/sensors_xacro_writer.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

double rotation_error(const model::Pose3& a, const model::Pose3& b) {
  const Eigen::AngleAxisd difference(a.linear().transpose() * b.linear());
  return std::abs(difference.angle());
}

// A rig whose mounts sit at the exported links of a description that holds only the parent
// link and the exported macro: the round trip rig -> xacro -> rig.
std::string round_trip_rig(const model::Rig& rig, const std::string& parent, bool optical) {
  std::string text =
      "name: round trip\nrobot:\n  description: wrapper.urdf.xacro\n"
      "  expander: builtin\n  base_link: " +
      parent + "\n  base_link_height: " + model::exact_number(rig.base_link_height) + "\n" +
      "body: {radius: 0.05, height: 0.1}\ndistance_of_interest: 5\nmounts:\n";
  for (const model::Mount& mount : rig.mounts) {
    text += "  - {id: " + mount.id + ", sensor: " + mount.sensor_id + ", mode: " + mount.mode_id +
            ", pose: {urdf_link: " + mount.id + (optical ? "_optical_frame" : "_link") + "}}\n";
  }
  return text;
}

}  // namespace

TEST_CASE("export: every bundled rig round-trips through its sensors.urdf.xacro", "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  for (const std::string name : {"ur_cleaner", "ur_cleaner_from_urdf", "delivery_amr", "elektron",
                                 "cell", "cart_two_scanners", "turtlebot4", "jackal"}) {
    INFO(name);
    const model::Rig rig = io::load_rig(source_path("rigs/" + name + ".yaml"));
    const deploy::SensorFrames frames = deploy::sensor_frames(rig, library);
    TempFolder folder;
    folder.write("sensors.urdf.xacro", io::sensors_xacro_text(frames, "round trip of " + name));
    folder.write("wrapper.urdf.xacro",
                 "<?xml version=\"1.0\"?>\n<robot name=\"wrapper\" "
                 "xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n  <link name=\"" +
                     frames.parent +
                     "\"/>\n  <xacro:include filename=\"sensors.urdf.xacro\"/>\n"
                     "  <xacro:rig_sensors/>\n</robot>\n");
    bool has_camera = false;
    for (const deploy::SensorFrame& frame : frames.frames)
      has_camera |= frame.optical_frame.has_value();
    // Through the body links; and, for cameras, through their optical frames, which the
    // loader turns back into body poses (REP-103) when the link's name says "optical".
    for (const bool optical : {false, true}) {
      if (optical && !has_camera) continue;
      model::Rig body_only = rig;
      if (optical) {
        // Only cameras have optical frames.
        std::erase_if(body_only.mounts, [&](const model::Mount& m) {
          const model::Sensor* sensor = library.find(m.sensor_id);
          return !sensor->find_mode(m.mode_id)->is_camera();
        });
      }
      const model::Rig back = io::load_rig(
          folder.write("round_trip.yaml", round_trip_rig(body_only, frames.parent, optical)));
      REQUIRE(back.mounts.size() == body_only.mounts.size());
      for (std::size_t i = 0; i < back.mounts.size(); ++i) {
        INFO(back.mounts[i].id << (optical ? " (optical frame)" : ""));
        // The read-back pose is in the wrapper's robot frame: the parent link lifted by the
        // base height, the same frame as the original's when the parent is the base link.
        CHECK((back.mounts[i].T_robot_sensor.translation() -
               body_only.mounts[i].T_robot_sensor.translation())
                  .norm() < 1e-9);
        CHECK(rotation_error(back.mounts[i].T_robot_sensor, body_only.mounts[i].T_robot_sensor) <
              1e-9);
      }
    }
  }
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
  const std::string text = io::sensors_xacro_text(deploy::sensor_frames(rig, library), "t");
  // rpy of that rotation: roll -pi/2, pitch 0, yaw -pi/2 (the usual camera optical joint).
  CHECK(text.find("rpy=\"-1.5707963267948966 0 -1.5707963267948966\"") != std::string::npos);
  CHECK(text.find("<child link=\"${prefix}front_camera_optical_frame\"/>") != std::string::npos);
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
