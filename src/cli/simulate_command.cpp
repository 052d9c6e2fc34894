// `rigdesign simulate RIG --scene NAME --frames N --seed S --out DIR [--gazebo]`: what every
// mounted sensor records in a synthetic scene, written as PCD (binary or ascii) or PLY clouds in
// the robot frame (or each sensor's frame), the sensor origin in the PCD VIEWPOINT; with
// --gazebo also the scene as a gz sim world.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <memory>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "inputs.hpp"
#include "progress_line.hpp"
#include "rigdesign/deploy/gazebo/scene_world_writer.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/cloud/cloud_io.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/sim/rig_simulation.hpp"
#include "rigdesign/sim/robot_occlusion.hpp"

namespace rigdesign::cli {
namespace {

// Rays whose robot stops them within the mode's range.
std::size_t hidden_rays(const std::vector<double>& free_ranges, double max_range) {
  return static_cast<std::size_t>(std::count_if(free_ranges.begin(), free_ranges.end(),
                                                [&](double free) { return free < max_range; }));
}

// Clouds one `simulate` run may write: a typo in --frames must not fill the disk.
constexpr double kMaxSimulationBytes = 2e9;

struct SimulateOptions {
  std::string rig;
  std::string scene = "office";
  int frames = 1;
  std::uint64_t seed = 1;
  std::string out;
  std::string format = "pcd";
  std::string frame = "robot";
  double dropout = 0.0;
  bool gazebo = false;  // --gazebo: the scene as gz sim loads it, too
};

int run_simulate(const SimulateOptions& options, std::ostream& out, std::ostream& err) {
  require_option(options.frames >= 1 && options.frames <= 100000, "--frames", "is out of range",
                 "1 to 100000");
  require_option(options.dropout >= 0 && options.dropout < 1, "--dropout", "is out of range",
                 "a share in [0, 1)");
  const RigInputs inputs = load_rig_inputs(options.rig, "", "", &err);
  const model::Scene scene = load_scene_option(options.scene, options.seed);
  sim::SimulationSettings settings;
  settings.dropout = options.dropout;
  settings.sensor_frame = options.frame == "sensor";
  const std::string folder =
      options.out.empty() ? "simulation/" + scene_label(options.scene) : options.out;
  const std::string extension = options.format == "ply" ? ".ply" : ".pcd";
  const io::CloudEncoding encoding =
      options.format == "pcd-ascii" ? io::CloudEncoding::ascii : io::CloudEncoding::binary;
  // Bounded before any work: at most the datasheet's points per frame, 12 bytes each in
  // binary (x y z floats), about 30 in ascii.
  double bytes = 0.0;
  for (const model::Mount& mount : inputs.rig.mounts) {
    const model::SensorMode& mode = *inputs.library.find(mount.sensor_id)->find_mode(mount.mode_id);
    bytes += mode.points_per_frame * options.frames *
             (encoding == io::CloudEncoding::ascii ? 30.0 : 12.0);
  }
  require_option(bytes <= kMaxSimulationBytes, "--frames",
                 std::to_string(options.frames) + " frames of this rig would write about " +
                     model::format_number(bytes / 1e9, 3) + " GB",
                 "at most 2 GB of clouds (they are held in memory per sensor): fewer frames");
  io::StagedFolder staged(folder, "--out");
  std::vector<std::string> read = files_read(inputs);
  read.push_back(options.scene);  // a scene file, or a bundled scene's name (never a file here)
  staged.refuse_inputs_inside(read);
  out << inputs.rig.name << " in the " << options.scene << " scene (seed " << options.seed << "), "
      << options.frames << " frame(s) per sensor, " << options.frame << " frame, at most "
      << model::format_number(bytes / 1e6, 3) << " MB\n";
  ProgressLine progress(err, "simulate: " + std::to_string(options.frames) + " frame(s) each",
                        "sensors");
  for (std::size_t i = 0; i < inputs.rig.mounts.size(); ++i) {
    progress.update(static_cast<double>(i), static_cast<double>(inputs.rig.mounts.size()));
    const model::Mount& mount = inputs.rig.mounts[i];
    const model::SensorMode& mode = *inputs.library.find(mount.sensor_id)->find_mode(mount.mode_id);
    // What the robot itself (body, parts, the other housings, supports) hides from each ray.
    const std::vector<double> free_ranges =
        sim::robot_free_ranges(inputs.rig, inputs.library, mount, mode, sim::ray_pattern(mode));
    const std::vector<model::PointCloud> clouds = sim::simulate_mount(
        scene, mount, mode, i, options.frames, options.seed, settings, free_ranges);
    io::prepare_output_folder(staged.path() + "/" + mount.id, "--out");
    std::size_t points = 0;
    for (std::size_t k = 0; k < clouds.size(); ++k) {
      io::write_cloud(staged.path() + "/" + mount.id + "/frame_" + std::to_string(k) + extension,
                      clouds[k], encoding);
      points += clouds[k].size();
    }
    progress.clear();
    out << "  " << mount.id << " (" << mount.sensor_id << "/" << mount.mode_id
        << "): " << points / clouds.size() << " points per frame -> " << folder << "/" << mount.id
        << "/ (its robot stops " << hidden_rays(free_ranges, mode.max_range) << " of "
        << free_ranges.size() << " rays)\n";
  }
  if (options.gazebo) {
    // The same scene for gz sim, so a Gazebo user simulates what rigdesign simulated.
    const std::string header = "Generated by rigdesign simulate --gazebo: scene " + options.scene +
                               ", seed " + std::to_string(options.seed);
    io::prepare_output_folder(staged.path() + "/gazebo", "--out");
    io::write_file_atomically(staged.path() + "/gazebo/scene.obj",
                              deploy::scene_obj_text(scene, header));
    io::write_file_atomically(staged.path() + "/gazebo/world.sdf",
                              deploy::gazebo_world_text(scene, "scene.obj", header));
    out << "  gz sim: " << folder << "/gazebo/world.sdf (the scene at t = 0, " << folder
        << "/gazebo/scene.obj)\n";
  }
  staged.commit();
  return kOk;
}

}  // namespace

Command setup_simulate(CLI::App& parent) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* app = parent.add_subcommand(
      "simulate", "Simulate what each mounted sensor records in a synthetic scene");
  add_rig_option(*app, options->rig);
  app->add_option(
      "--scene", options->scene,
      "office, corridor, stairs, wall_following, cell, or a scene file (default office)");
  app->add_option("--frames", options->frames, "Frames per sensor (default 1)");
  add_seed_option(*app, options->seed, "the scene and the sensor noise (default 1)");
  add_out_option(*app, options->out, "the clouds (default simulation/<scene>)");
  // --format asks every other command for text or JSON; here it is the clouds' file format.
  CLI::Option* cloud_format = app->add_option("--cloud-format", options->format,
                                              "pcd (binary), pcd-ascii or ply (default pcd)")
                                  ->check(CLI::IsMember({"pcd", "pcd-ascii", "ply"}));
  cloud_format->excludes(
      app->add_option("--format", options->format, "Former name of --cloud-format")
          ->check(CLI::IsMember({"pcd", "pcd-ascii", "ply"}))
          ->group(""));
  app->add_option("--frame", options->frame, "robot or sensor frame (default robot)")
      ->check(CLI::IsMember({"robot", "sensor"}));
  app->add_option("--dropout", options->dropout, "Share of rays that return nothing (default 0)");
  app->add_flag("--gazebo", options->gazebo,
                "Also write the scene for gz sim: gazebo/world.sdf and gazebo/scene.obj");
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_simulate(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
