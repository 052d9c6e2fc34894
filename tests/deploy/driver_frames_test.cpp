// Issue 30 item 5: the export names frames and topics as the sensors' ROS 2 drivers publish
// them. Expected names are read from the driver research (data/ros_drivers, each fact cited
// to the driver's source), not from sensors.yaml or the program.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/ros/description/sensors_xacro_writer.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// The research entry of `sensor` in data/ros_drivers/`file`.
YAML::Node researched(const std::string& file, const std::string& sensor) {
  for (const YAML::Node& entry : YAML::LoadFile(source_path("data/ros_drivers/" + file))) {
    if (entry["sensor"].as<std::string>() == sensor) return entry;
  }
  FAIL("no research entry for " << sensor);
  return {};
}

std::string rig_text(const std::string& mounts) {
  return "name: drivers\nsensor_library: " + source_path("sensors.yaml") +
         "\nbody: {radius: 0.3, height: 0.5}\ndistance_of_interest: 3.0\nmounts:\n" + mounts;
}

const deploy::SourceConfig& source_of(const deploy::Deployment& d, const std::string& mount) {
  for (const deploy::SourceConfig& source : d.costmap.sources) {
    if (source.mount_id == mount) return source;
  }
  FAIL("no source " << mount);
  return d.costmap.sources.front();
}

}  // namespace

TEST_CASE("export: a lone lidar and camera take their drivers' frames and topics", "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  TempFolder folder;
  const model::Rig rig = io::load_rig(folder.write(
      "rig.yaml", rig_text("  - {id: top, sensor: velodyne_vlp16, mode: vlp16_10hz,\n"
                           "     pose: {xyz: [0, 0, 0.6], rpy_deg: [0, 0, 0]}}\n"
                           "  - {id: front, sensor: realsense_d435, mode: z16_848x480_30,\n"
                           "     pose: {xyz: [0.31, 0, 0.4], rpy_deg: [0, 20, 0]}}\n")));
  const deploy::Deployment d = deploy::plan_deployment(rig, library, nullptr, {});
  const YAML::Node velodyne = researched("drivers_a.yaml", "velodyne_vlp16");
  CHECK(source_of(d, "top").raw_topic == velodyne["data"]["topic"].as<std::string>());
  CHECK(source_of(d, "top").sensor_frame == velodyne["data"]["frame_id"].as<std::string>());
  CHECK(d.frames.frames[0].link == velodyne["data"]["frame_id"].as<std::string>());
  // realsense2_camera broadcasts camera_link -> ... -> camera_depth_optical_frame itself: the
  // URDF gives camera_link (with the D435's datasheet housing) at the sensor, the costmap
  // reads the depth optical frame.
  const YAML::Node realsense = researched("drivers_a.yaml", "realsense_d435");
  CHECK(source_of(d, "front").raw_topic == realsense["data"]["topic"].as<std::string>());
  CHECK(source_of(d, "front").sensor_frame == realsense["data"]["frame_id"].as<std::string>());
  CHECK(d.frames.frames[1].link == realsense["driver_tf_frames"][0].as<std::string>());
  const std::string xacro = deploy::sensors_xacro_text(d.frames, "t");
  CHECK(xacro.find("<link name=\"${prefix}camera_link\">") != std::string::npos);
  CHECK(xacro.find("camera_depth_optical_frame") == std::string::npos);
}

TEST_CASE("export: two mounts of one driver get namespaces and their own frames, with a note",
          "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  TempFolder folder;
  const model::Rig rig = io::load_rig(folder.write(
      "rig.yaml", rig_text("  - {id: front_lidar, sensor: rplidar_a2m8, mode: 10hz,\n"
                           "     pose: {xyz: [0.31, 0, 0.2], rpy_deg: [0, 0, 0]}}\n"
                           "  - {id: rear_lidar, sensor: rplidar_a2m8, mode: 10hz,\n"
                           "     pose: {xyz: [-0.31, 0, 0.2], rpy_deg: [0, 0, 180]}}\n")));
  const deploy::Deployment d = deploy::plan_deployment(rig, library, nullptr, {});
  const YAML::Node sllidar = researched("drivers_b.yaml", "rplidar_a2m8");
  const std::string topic = sllidar["data"]["topic"].as<std::string>();  // /scan
  CHECK(source_of(d, "front_lidar").raw_topic == "/front_lidar" + topic);
  CHECK(source_of(d, "rear_lidar").raw_topic == "/rear_lidar" + topic);
  CHECK(source_of(d, "front_lidar").topic_note.find("namespace front_lidar") != std::string::npos);
  // Both drivers would stamp 'laser': each mount keeps its own link, and says how to set it.
  CHECK(d.frames.frames[0].link == "front_lidar_link");
  CHECK(d.frames.frames[0].note.find("'" + sllidar["data"]["frame_id"].as<std::string>() +
                                     "' by default") != std::string::npos);
  CHECK(d.frames.frames[0].note.find("front_lidar_link") != std::string::npos);
}

TEST_CASE("export: a mount's ros map sets its topic, namespace and frame", "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  TempFolder folder;
  const model::Rig rig = io::load_rig(folder.write(
      "rig.yaml",
      rig_text("  - {id: top, sensor: velodyne_vlp16, mode: vlp16_10hz,\n"
               "     pose: {xyz: [0, 0, 0.6]}, ros: {topic: /lidar/points, frame: top_lidar}}\n"
               "  - {id: front, sensor: realsense_d435, mode: z16_848x480_30,\n"
               "     pose: {xyz: [0.31, 0, 0.4]}, ros: {namespace: front}}\n")));
  const deploy::Deployment d = deploy::plan_deployment(rig, library, nullptr, {});
  CHECK(source_of(d, "top").raw_topic == "/lidar/points");
  CHECK(source_of(d, "top").sensor_frame == "top_lidar");
  CHECK(d.frames.frames[0].link == "top_lidar");
  CHECK(source_of(d, "front").raw_topic == "/front/camera/camera/depth/color/points");
  // A relative topic or a bad frame id is refused at its key.
  const std::string bad = folder.write(
      "bad.yaml", rig_text("  - {id: top, sensor: velodyne_vlp16, mode: vlp16_10hz,\n"
                           "     pose: {xyz: [0, 0, 0.6]}, ros: {topic: lidar/points}}\n"));
  CHECK_THROWS_WITH(io::load_rig(bad), Catch::Contains("mounts[0].ros.topic: is relative"));
}

TEST_CASE("export CLI: a topic template that is no ROS name exits 2 and writes nothing",
          "[deploy]") {
  TempFolder folder;
  const CliResult result = run_cli({"export", source_path("rigs/cart_two_scanners.yaml"), "--to",
                                    folder.path() + "/out", "--scan-topic", "/{mount}/scan\nx: 1"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--scan-topic") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(folder.path() + "/out"));
}
