// Issue 34 item 4: a Clearpath robot.yaml's sensors into a rig and back. The sample is written
// from clearpath_config's documented schema (tests/data/clearpath/j100_robot.yaml); expected
// values are its text, read here with yaml-cpp, not with rigdesign's reader.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "rigdesign/deploy/clearpath/clearpath_sensors.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using test::CliResult;
using test::run_cli;
using test::source_path;

namespace {

const std::string kSample = "tests/data/clearpath/j100_robot.yaml";

// The entry of `type` whose model is `model` in a robot.yaml document.
YAML::Node entry_of(const YAML::Node& document, const std::string& type, const std::string& model) {
  for (const YAML::Node& entry : document["sensors"][type])
    if (entry["model"].as<std::string>() == model) return entry;
  return YAML::Node();
}

}  // namespace

TEST_CASE("clearpath: robot.yaml's range sensors map to library sensors by model and device",
          "[io]") {
  const deploy::ClearpathRobot robot = deploy::read_clearpath_robot(source_path(kSample));
  CHECK(robot.serial_number == "j100-0000");
  CHECK(robot.ros_namespace == "j100_0000");
  REQUIRE(robot.sensors.size() == 3);
  CHECK(robot.sensors[0].name() == "lidar2d_0");
  CHECK(robot.sensors[0].sensor_id == "hokuyo_ust_10lx");
  CHECK(robot.sensors[1].name() == "lidar3d_0");
  CHECK(robot.sensors[1].sensor_id == "velodyne_vlp32c");  // velodyne_driver_node.model: 32C
  CHECK(robot.sensors[2].name() == "camera_0");
  CHECK(robot.sensors[2].sensor_id == "realsense_d415");  // intel_realsense.device_type: d415
  CHECK(robot.sensors[2].rpy.y() == 0.2);
  // The colour camera and the IMU are not range sensors: listed, not imported.
  CHECK(robot.skipped.size() == 2);
}

TEST_CASE("clearpath: ros_parameters without the device's node leave the default (fuzz finding)",
          "[io]") {
  // libFuzzer's input: the driver node's name misspelt, so the device key is absent; reading
  // it used to throw yaml-cpp's InvalidNode instead of taking the model's default device.
  test::TempFolder folder;
  const std::string path =
      folder.write("robot.yaml",
                   "version: 0\nsensors:\n  lidar3d:\n    - model: velodyne_lidar\n"
                   "      ros_parameters: {ve`odyne_driver_node: {model: 32C}}\n");
  const deploy::ClearpathRobot robot = deploy::read_clearpath_robot(path);
  REQUIRE(robot.sensors.size() == 1);
  CHECK(robot.sensors[0].sensor_id == "velodyne_vlp16");  // VLP16, the default device
}

TEST_CASE("clearpath: sensor kinds a newer clearpath_config adds are not refused", "[io]") {
  test::TempFolder folder;
  const std::string path =
      folder.write("robot.yaml",
                   "serial_number: a300-0000\nversion: 0\nsensors:\n  ins:\n"
                   "    - {model: some_ins}\n  lidar2d:\n    - {model: sick_lms1xx}\n");
  const deploy::ClearpathRobot robot = deploy::read_clearpath_robot(path);
  REQUIRE(robot.sensors.size() == 1);
  CHECK(robot.sensors[0].sensor_id == "sick_lms100");
  CHECK(robot.sensors[0].parent == "default_mount");  // clearpath_config's default
}

TEST_CASE("clearpath: import onto the Jackal, export, and the sensors section comes back", "[io]") {
  test::TempFolder folder;
  const std::string rig = folder.path() + "/j100.yaml";
  CliResult result = run_cli({"clearpath-import", source_path(kSample), "--rig",
                              source_path("rigs/jackal.yaml"), "--to", rig});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  result = run_cli({"export", rig, "--to", folder.path() + "/deploy"});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  const YAML::Node sample = YAML::LoadFile(source_path(kSample));
  const YAML::Node written = YAML::LoadFile(folder.path() + "/deploy/clearpath_sensors.yaml");
  for (const auto& [type, model] :
       {std::pair{"lidar2d", "hokuyo_ust"}, std::pair{"lidar3d", "velodyne_lidar"},
        std::pair{"camera", "intel_realsense"}}) {
    INFO(type << " " << model);
    const YAML::Node given = entry_of(sample, type, model);
    const YAML::Node back = entry_of(written, type, model);
    REQUIRE(back.IsMap());
    CHECK(back["parent"].as<std::string>() == given["parent"].as<std::string>());
    for (const char* key : {"xyz", "rpy"}) {
      for (std::size_t i = 0; i < 3; ++i)
        CHECK(back[key][i].as<double>() == Approx(given[key][i].as<double>()).margin(1e-9));
    }
  }
  CHECK(written["sensors"]["lidar3d"][0]["ros_parameters"]["velodyne_driver_node"]["model"]
            .as<std::string>() == "32C");
  CHECK(written["sensors"]["camera"][0]["ros_parameters"]["intel_realsense"]["device_type"]
            .as<std::string>() == "d415");
  // Frames and topics as clearpath_config names them reach the nav2 file.
  const YAML::Node nav2 = YAML::LoadFile(folder.path() + "/deploy/nav2_costmap.yaml");
  const YAML::Node layer = nav2["local_costmap"]["local_costmap"]["ros__parameters"]["voxel_layer"];
  CHECK(layer["lidar2d_0"]["sensor_frame"].as<std::string>() == "lidar2d_0_laser");
  CHECK(layer["lidar3d_0"]["sensor_frame"].as<std::string>() == "lidar3d_0_laser");
  CHECK(layer["camera_0"]["sensor_frame"].as<std::string>() == "camera_0_depth_optical_frame");
  CHECK(layer["lidar3d_0"]["topic"].as<std::string>().rfind("/j100_0000/sensors/lidar3d_0/points",
                                                            0) == 0);
}

TEST_CASE("clearpath: an unknown model, a short xyz, an unknown parent exit 2 at file:line:col",
          "[io]") {
  test::TempFolder folder;
  const std::string bad_model =
      folder.write("model.yaml",
                   "serial_number: j100-0000\nversion: 0\nsensors:\n  lidar2d:\n"
                   "    - model: lidar_from_mars\n      parent: base_link\n");
  CliResult result = run_cli({"clearpath-import", bad_model, "--rig",
                              source_path("rigs/jackal.yaml"), "--to", folder.path() + "/r.yaml"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find(bad_model + ":5:14") != std::string::npos);
  CHECK(result.err.find("hokuyo_ust, sick_lms1xx") != std::string::npos);
  const std::string short_xyz =
      folder.write("xyz.yaml",
                   "version: 0\nsensors:\n  lidar2d:\n    - model: hokuyo_ust\n"
                   "      xyz: [0.1, 0.2]\n");
  result = run_cli({"clearpath-import", short_xyz, "--rig", source_path("rigs/jackal.yaml"), "--to",
                    folder.path() + "/r.yaml"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find(short_xyz + ":5:12") != std::string::npos);
  CHECK(result.err.find("xyz") != std::string::npos);
  const std::string bad_parent =
      folder.write("parent.yaml",
                   "version: 0\nsensors:\n  lidar2d:\n    - model: hokuyo_ust\n"
                   "      parent: top_plate_front_mount\n");
  result = run_cli({"clearpath-import", bad_parent, "--rig", source_path("rigs/jackal.yaml"),
                    "--to", folder.path() + "/r.yaml"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find(bad_parent + ":5:15: parent") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(folder.path() + "/r.yaml"));  // nothing half-written
}

TEST_CASE("clearpath: a sensor the robot.yaml puts inside the chassis is a warning at its entry",
          "[io]") {
  test::TempFolder folder;
  // 0.1 m above base_link, inside the chassis box (0 to 0.184 m above base_link, x within
  // +-0.21 m: jackal.urdf.xacro lines 13-15 and 112). The entry starts on line 5.
  const std::string robot_yaml = folder.write(
      "robot.yaml",
      "serial_number: j100-0000\nversion: 0\nsensors:\n  lidar2d:\n    - model: hokuyo_ust\n"
      "      parent: base_link\n      xyz: [0.19, 0.0, 0.1]\n      rpy: [0.0, 0.0, 0.0]\n");
  const CliResult result =
      run_cli({"clearpath-import", robot_yaml, "--rig", source_path("rigs/jackal.yaml"), "--to",
               folder.path() + "/rig.yaml"});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 0);
  CHECK(result.out.find("robot.yaml:5:") != std::string::npos);
  CHECK(result.out.find("inside the collision geometry of link 'chassis_link'") !=
        std::string::npos);
}
