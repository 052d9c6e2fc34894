// `rigdesign export RIG --out DIR [--parent LINK] [--scan-topic T] [--cloud-topic T]
// [--max-speed V] [--update-rate F] [--hit-layer-plugin CLASS]`: writes what the rig means for its
// ROS 2 stack (issue 14): the sensors' URDF macro, nav2 costmap parameters, self-filters; prints
// how each was derived.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <ostream>
#include <utility>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "inputs.hpp"
#include "number_checks.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/export/deployment_files.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/model/ros_names.hpp"
#include "rigdesign/render/gltf_scene.hpp"
#include "rigdesign/report/deployment_report.hpp"

namespace rigdesign::cli {
namespace {

struct ExportOptions {
  std::string rig;
  std::string sensors;
  std::string requirements;
  std::string to;
  std::string layer = "voxel";       // --layer voxel|stvl
  double processing_latency = -1.0;  // --processing-latency; negative: not given
  bool gltf = false;                 // --gltf: the body and FOV volumes as rig_fov.gltf
  deploy::DeployOptions deploy;
};

// pluginlib's class names: namespace::Class (nav2) or package/Class (STVL).
bool plugin_class_name(const std::string& name) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  const std::size_t colons = name.find("::");
  const std::size_t slash = name.find('/');
  const std::size_t split = colons != std::string::npos ? colons : slash;
  if (split == std::string::npos || split == 0) return false;
  const std::size_t rest = split + (colons != std::string::npos ? 2 : 1);
  if (rest >= name.size()) return false;
  const std::string head = name.substr(0, split);
  const std::string tail = name.substr(rest);
  return std::all_of(head.begin(), head.end(), word) &&
         std::all_of(tail.begin(), tail.end(), [&](char c) { return word(c) || c == ':'; });
}

int run_export(const ExportOptions& given, std::ostream& out) {
  ExportOptions options = given;
  require_option(options.deploy.ros_distro == "humble" || options.deploy.ros_distro == "jazzy",
                 "--ros-distro", "is '" + options.deploy.ros_distro + "'", "humble or jazzy");
  require_option(options.layer == "voxel" || options.layer == "stvl", "--layer",
                 "is '" + options.layer + "'", "voxel or stvl");
  options.deploy.stvl = options.layer == "stvl";
  if (options.processing_latency >= 0.0)
    options.deploy.processing_latency = options.processing_latency;
  require_option(options.deploy.max_speed >= 0.0, "--max-speed", "must not be negative",
                 "a speed in m/s (0: the requirements' R5 speed)");
  require_option(options.deploy.min_speed > 0.0 && std::isfinite(options.deploy.min_speed),
                 "--min-speed", "must be positive", "a speed in m/s, > 0");
  require_option(std::isfinite(options.deploy.max_speed), "--max-speed", "is not a number",
                 "a speed in m/s");
  require_option(options.deploy.update_rate > 0.0 && options.deploy.update_rate <= 100.0,
                 "--update-rate", "is out of range", "0 < rate <= 100 Hz");
  for (const auto& [name, text] : {std::pair{"--scan-topic", &options.deploy.scan_topic},
                                   std::pair{"--cloud-topic", &options.deploy.cloud_topic}}) {
    require_option(text->empty() || model::is_topic_name(deploy::expand_topic(*text, "mount")),
                   name, "'" + *text + "' is not a ROS topic name",
                   "tokens of letters, digits and underscores joined by '/', e.g. /{mount}/scan");
  }
  const std::string& plugin = options.deploy.hit_layer_plugin;
  require_option(plugin.empty() || plugin_class_name(plugin), "--hit-layer-plugin",
                 "'" + plugin + "' is not a pluginlib class name",
                 "package::Class or package/Class (letters, digits, '_')");
  const RigInputs inputs =
      load_rig_inputs(options.rig, options.sensors, options.requirements, &out);
  const model::Requirements* requirements = inputs.requirements ? &*inputs.requirements : nullptr;
  const deploy::Deployment deployment =
      deploy::plan_deployment(inputs.rig, inputs.library, requirements, options.deploy);
  // Staged as a whole: a full disk or a kill leaves the previous export or the new one,
  // never the new macro beside the old costmap file.
  require_option(!options.to.empty(), "--out", "is missing", "--out FOLDER for the files");
  io::StagedFolder staged(options.to, "--out");
  staged.refuse_inputs_inside(files_read(inputs));
  std::vector<std::string> written = deploy::write_deployment(
      staged.path(), inputs.rig, deployment, report::deployment_header(inputs.rig, requirements));
  if (options.gltf) {
    written.push_back(staged.path() + "/rig_fov.gltf");
    io::write_file_atomically(
        written.back(),
        render::gltf_scene(inputs.rig.name, inputs.rig.base_link, inputs.rig.base_link_height,
                           render::rig_gltf_parts(inputs.rig, inputs.library)));
  }
  staged.commit();
  report::print_deployment(out, inputs.rig, deployment, staged.final_names(written));
  return kOk;
}

}  // namespace

Command setup_export(CLI::App& parent) {
  auto options = std::make_shared<ExportOptions>();
  CLI::App* app = parent.add_subcommand(
      "export",
      "Write the rig's ROS 2 configuration: sensors.urdf.xacro, nav2_costmap.yaml, "
      "self_filters.yaml and its launch file, and for gz sim sensors.gazebo.xacro and "
      "bridge.yaml");
  add_rig_option(*app, options->rig);
  add_out_option(*app, options->to, "the deployment's files, required (created if missing)",
                 "--to");
  add_sensors_option(*app, options->sensors);
  // R5's speed sizes the blind-gap memory.
  add_requirements_option(*app, options->requirements);
  app->add_option("--parent", options->deploy.parent,
                  "Parent link of the sensor joints (default: the rig's base link, "
                  "base_footprint without a description)");
  app->add_option("--scan-topic", options->deploy.scan_topic,
                  "Topic of 2D scanners, {mount} is the mount id (default: each driver's "
                  "topic, sensors.yaml ros2; without a driver /{mount}/scan)");
  app->add_option("--cloud-topic", options->deploy.cloud_topic,
                  "Topic of 3D sensors, {mount} is the mount id (default: each driver's "
                  "topic; without a driver /{mount}/points)");
  app->add_option("--max-speed", options->deploy.max_speed,
                  "Robot speed [m/s] for the blind-gap memory rule (default: the requirements' R5)")
      ->check(positive_up_to(10.0, "a speed in (0, 10] m/s"));
  app->add_option("--min-speed", options->deploy.min_speed,
                  "Slowest driving speed [m/s] the memory must outlast a blind gap at "
                  "(default 0.25, nav2 Regulated Pure Pursuit's regulated minimum)")
      ->check(positive_up_to(10.0, "a speed in (0, 10] m/s"));
  app->add_option("--update-rate", options->deploy.update_rate,
                  "Local costmap update rate [Hz] (default 5, nav2's)")
      ->check(positive_up_to(100.0, "a rate in (0, 100] Hz"));
  app->add_option("--global-frame-height", options->deploy.global_frame_height,
                  "Height [m] of the costmaps' global frame (odom) above the floor: the height "
                  "bands are written in that frame (Clearpath's 2D EKF: the base link's "
                  "height). Default 0, stated in the file")
      ->check(finite_in(-10.0, 10.0, "a height in metres within +-10"));
  app->add_option("--layer", options->layer,
                  "The 3D sensors' costmap layer: voxel (nav2's VoxelLayer, default) or stvl "
                  "(spatio_temporal_voxel_layer; 2D scanners stay in nav2's ObstacleLayer)");
  app->add_option("--ros-distro", options->deploy.ros_distro,
                  "nav2 release the collision monitor's file is written for: jazzy (default; "
                  "points as a string, per-zone sources_names) or humble");
  app->add_option("--processing-latency", options->processing_latency,
                  "Driver and filter time per frame [s] in each source's latency, which sizes "
                  "the collision monitor's zones (default: one frame period, the most a chain "
                  "that keeps up with its sensor takes)")
      ->check(finite_in(0.0, 10.0, "seconds in [0, 10]"));
  app->add_flag("--gltf", options->gltf,
                "Also write rig_fov.gltf: the body and each mount's FOV volume (cut where the "
                "body blocks it) as glTF 2.0, for Foxglove, RViz's mesh marker or Blender");
  app->add_option("--hit-layer-plugin", options->deploy.hit_layer_plugin,
                  "Add paper 1's Hit Layer as this costmap plugin class (one you built; nav2 "
                  "has none). Default: none, nav2's observation_persistence remembers the "
                  "blind gaps");
  return {app, [options](std::ostream& out, std::ostream&) { return run_export(*options, out); }};
}

}  // namespace rigdesign::cli
