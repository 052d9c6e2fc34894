// `rigdesign clearpath-import ROBOT_YAML --rig BASE_RIG --to RIG_OUT`: a Clearpath robot.yaml's
// range sensors as a rig (issue 34 item 4): the base rig's body, description and settings, its
// mounts replaced by the robot.yaml's lidar2d, lidar3d and camera entries, each named and
// wired the way clearpath_config names it (<type>_<index>, its topic and a lidar's frame).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "inputs.hpp"
#include "rigdesign/deploy/clearpath/clearpath_sensors.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/yaml_writers.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/metrics/mount_placement_verdicts.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rotation.hpp"

namespace rigdesign::cli {
namespace {

struct ClearpathImportOptions {
  std::string robot_yaml;
  std::string rig;
  std::string to;
};

// Where clearpath_config puts the data (sensors/types/*.py; docs/clearpath.md): topics under
// <namespace>/sensors/<name>/, a lidar's frame <name>_laser (set on every index change), a
// RealSense's depth frame <name>_depth_optical_frame.
void wire_like_clearpath(const deploy::ClearpathSensor& sensor, const std::string& ros_namespace,
                         model::Mount& mount) {
  const std::string base =
      (ros_namespace.empty() ? "" : "/" + ros_namespace) + "/sensors/" + sensor.name() + "/";
  mount.ros_topic = base + (sensor.type == "lidar2d" ? "scan" : "points");
  if (sensor.type != "camera") mount.ros_frame = sensor.name() + "_laser";
  // clearpath_config names a RealSense after the sensor (camera_name: camera_0), and
  // realsense2_camera prefixes its frames with the camera name.
  if (sensor.model == "intel_realsense") mount.ros_frame = sensor.name() + "_depth_optical_frame";
}

int run_clearpath_import(const ClearpathImportOptions& options, std::ostream& out) {
  RigInputs inputs = load_rig_inputs(options.rig, "", "");
  const deploy::ClearpathRobot robot = deploy::read_clearpath_robot(options.robot_yaml);
  std::vector<model::Mount> mounts;
  model::Diagnostics diagnostics;
  for (const deploy::ClearpathSensor& sensor : robot.sensors) {
    const std::optional<model::Pose3> T_robot_parent =
        deploy::robot_frame_pose(inputs.rig, sensor.parent);
    if (!T_robot_parent) {
      diagnostics.error(
          sensor.parent_where, "parent",
          "'" + sensor.parent + "' is not a link of " + inputs.rig.file + "'s robot description",
          "base_footprint or a link of the base rig's description (its robot: "
          "Clearpath's own description for mount links such as default_mount)");
      continue;
    }
    const model::Sensor* library_sensor = inputs.library.find(sensor.sensor_id);
    if (library_sensor == nullptr || library_sensor->modes.empty()) {
      diagnostics.error(
          sensor.where, "model",
          "maps to '" + sensor.sensor_id + "', which " + inputs.library.file + " does not hold",
          "a sensor library with " + sensor.sensor_id);
      continue;
    }
    model::Mount mount;
    mount.id = sensor.name();
    mount.pose_where = sensor.where;  // findings about its place point at the robot.yaml entry
    mount.sensor_id = sensor.sensor_id;
    mount.mode_id = library_sensor->modes.front().id;  // the sensor's first (default) mode
    model::Pose3 T_parent_sensor = model::Pose3::Identity();
    T_parent_sensor.translation() = sensor.xyz;
    T_parent_sensor.linear() =
        model::rotation_from_rpy(sensor.rpy.x(), sensor.rpy.y(), sensor.rpy.z());
    mount.T_robot_sensor = *T_robot_parent * T_parent_sensor;
    wire_like_clearpath(sensor, robot.ros_namespace, mount);
    mounts.push_back(mount);
  }
  diagnostics.throw_if_errors();
  require_option(!mounts.empty(), "ROBOT_YAML", options.robot_yaml + " has no range sensor",
                 "a robot.yaml with lidar2d, lidar3d or camera entries");
  inputs.rig.mounts = mounts;
  inputs.rig.name = (robot.serial_number.empty() ? std::string("robot") : robot.serial_number) +
                    " (sensors from " +
                    std::filesystem::path(options.robot_yaml).filename().string() + ")";
  const std::string folder = std::filesystem::path(options.to).parent_path().string();
  const std::string where = folder.empty() ? "." : folder;
  if (!folder.empty()) io::prepare_output_folder(folder, "--to");
  io::write_file_atomically(
      options.to,
      io::rig_to_yaml(
          inputs.rig, io::path_seen_from(inputs.library.file, where),
          inputs.rig.requirements.empty()
              ? ""
              : io::path_seen_from(
                    (std::filesystem::path(inputs.rig.file).parent_path() / inputs.rig.requirements)
                        .string(),
                    where),
          "Imported by `rigdesign clearpath-import` from " + options.robot_yaml + " onto " +
              options.rig + "; modes are each sensor's first",
          where));
  out << "wrote " << options.to << ": " << mounts.size() << " mount(s) from " << options.robot_yaml
      << '\n';
  for (const model::Mount& mount : mounts)
    out << "  " << mount.id << ": " << mount.sensor_id << " / " << mount.mode_id << ", topic "
        << mount.ros_topic << (mount.ros_frame.empty() ? "" : ", frame " + mount.ros_frame) << '\n';
  for (const std::string& skipped : robot.skipped) out << "  skipped " << skipped << '\n';
  // A sensor the robot.yaml puts inside the body could not be bolted there (check's B1).
  for (const model::Diagnostic& warning : metrics::placement_warnings(inputs.rig, inputs.library))
    out << warning.message() << '\n';
  return kOk;
}

}  // namespace

Command setup_clearpath_import(CLI::App& parent) {
  auto options = std::make_shared<ClearpathImportOptions>();
  CLI::App* app = parent.add_subcommand(
      "clearpath-import",
      "Read a Clearpath robot.yaml's lidar2d, lidar3d and camera entries into a rig");
  app->add_option("robot_yaml", options->robot_yaml, "Clearpath robot.yaml")->required();
  app->add_option("--rig", options->rig,
                  "Base rig: its body, robot description and settings (its mounts are replaced)")
      ->required();
  app->add_option("--to", options->to, "Rig file to write")->required();
  return {app, [options](std::ostream& out, std::ostream&) {
            return run_clearpath_import(*options, out);
          }};
}

}  // namespace rigdesign::cli
