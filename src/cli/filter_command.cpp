// `rigdesign filter --cloud FILE... --pipeline P1..P4|FILE [--rig RIG --mount ID]`: runs a
// filter pipeline on point clouds and reports, per stage, the median and p95 time (model::median,
// model::percentile) and the
// points in and out (paper 1, section 3). A cloud recorded in a sensor's optical frame is
// moved into the robot frame by the mount's pose first, so the floor stages find the floor.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "inputs.hpp"
#include "machine_info.hpp"
#include "progress_line.hpp"
#include "rigdesign/filters/pipeline.hpp"
#include "rigdesign/filters/pipeline_timing.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/cloud/cloud_io.hpp"
#include "rigdesign/io/config/filtering_loads_io.hpp"
#include "rigdesign/io/config/pipeline_loader.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/metrics/mount_metrics.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "rigdesign/report/filter_json.hpp"
#include "rigdesign/report/filter_report.hpp"
#include "rigdesign/report/filter_text.hpp"
#include "rigdesign/sim/rig_simulation.hpp"

namespace rigdesign::cli {
namespace {

struct FilterOptions {
  std::vector<std::string> clouds;
  std::string scene;
  int frames = 20;
  std::uint64_t seed = 1;
  std::string pipeline = "P4";
  std::string rig;
  std::string mount;
  std::string frame = "auto";
  std::string out;
  std::string write_loads;
  int repeat = 10;
  int threads = 0;  // 0: as the pipeline says (1 unless its file sets threads)
  bool json = false;
};

model::Pipeline pipeline_named(const std::string& name) {
  if (const auto preset = filters::preset_pipeline(name)) return *preset;
  std::error_code error;
  if (std::filesystem::is_regular_file(name, error)) return io::load_pipeline(name);
  throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                            "--pipeline",
                                            "'" + name + "' is neither a preset nor a file",
                                            "P1, P2, P3, P4, P2_paper2 or a pipeline YAML file"});
}

// Merged into what the file already holds, so loads measured on several rigs collect there.
void write_loads(const std::string& path, const model::FilteringLoads& measured,
                 const std::string& rig_file) {
  std::error_code error;
  const model::FilteringLoads previous = std::filesystem::is_regular_file(path, error)
                                             ? io::load_filtering_loads(path)
                                             : model::FilteringLoads{};
  const std::string comment =
      "Measured filtering load per delivered point (paper 1, eq. 5: U_f = seconds_per_point x "
      "points/s),\n"
      "written by `rigdesign filter --write-loads` (last: " +
      rig_file +
      "). Catalogs read it through\n"
      "`filtering_loads:`; `rigdesign metrics --filtering-loads` prints U_f from it.";
  io::write_file_atomically(
      path, io::filtering_loads_to_yaml(io::merge_filtering_loads(previous, measured), comment));
}

// Every mount of the rig in a synthetic scene: its frames through the pipeline, and the
// filtering load U_f = median time per frame x frame rate (paper 1, eq. 5).
int run_filter_on_scene(const FilterOptions& options, const model::Pipeline& pipeline,
                        std::ostream& out, std::ostream& err) {
  const RigInputs inputs = load_rig_inputs(options.rig, "", "");
  require_option(options.frames >= 1 && options.frames <= 10000, "--frames", "is out of range",
                 "1 to 10000");
  const model::Scene scene = load_scene_option(options.scene, options.seed);
  report::FilterSceneReport report{
      inputs.rig.name, options.scene, pipeline.name, options.frames, {}, 0.0, options.write_loads};
  ProgressLine progress(
      err, "filter: simulate and time " + std::to_string(options.frames) + " frame(s) each",
      "sensors");
  model::FilteringLoads measured{
      describe_machine(), pipeline.name, options.scene, options.frames, {}, {}};
  for (std::size_t i = 0; i < inputs.rig.mounts.size(); ++i) {
    progress.update(static_cast<double>(i), static_cast<double>(inputs.rig.mounts.size()));
    const model::Mount& mount = inputs.rig.mounts[i];
    const model::SensorMode& mode = *inputs.library.find(mount.sensor_id)->find_mode(mount.mode_id);
    // Raw clouds, as the filters receive them: a ray the robot stops returns a point on the
    // robot there (the self-filter's work), so no ray is dropped for the robot here.
    const std::vector<model::PointCloud> clouds =
        sim::simulate_mount(scene, mount, mode, i, options.frames, options.seed);
    const filters::FramesLoad load =
        filters::measure_filtering_load(pipeline, clouds, mode.frequency);
    report.mounts.push_back({mount.id, mode.frequency, load.points / clouds.size(),
                             load.kept / clouds.size(), load.seconds_per_frame, load.load});
    report.total_load_cores += load.load.cores;
    measured.record({mount.sensor_id,
                     mount.mode_id,
                     load.load.seconds_per_point,
                     static_cast<double>(load.points) / static_cast<double>(clouds.size()),
                     load.seconds_per_frame.median,
                     {}});
  }
  progress.clear();  // the report follows on standard output
  if (!options.write_loads.empty()) write_loads(options.write_loads, measured, inputs.rig.file);
  if (options.json) {
    out << report::filter_scene_json(report).dump(2) << '\n';
  } else {
    report::print_filter_scene(report, out);
  }
  return kOk;
}

// One cloud file through the pipeline: moved into the robot frame when a mount recorded it,
// timed over the runs, its load at the mount's rate, the result written with --out.
report::FilterCloudReport filter_cloud(const std::string& path, const FilterOptions& options,
                                       const model::Pipeline& pipeline, const model::Mount* mount,
                                       const model::SensorMode* mode) {
  io::CloudReadReport read;
  model::PointCloud cloud = io::read_cloud(path, &read);
  if (cloud.empty()) {
    throw model::InputError(model::Diagnostic{
        {path, 0, 0}, "data", "has no finite point to filter", "a non-empty cloud"});
  }
  // Clouds arrive as drivers publish them (and as `simulate --frame sensor` writes them):
  // a camera's in its optical frame, a lidar's in its x-forward frame.
  const std::string frame =
      options.frame != "auto" ? options.frame : (mode && mode->is_camera() ? "optical" : "sensor");
  if (mount != nullptr && frame != "robot") {
    const model::Pose3 T_robot_cloud = frame == "optical"
                                           ? mount->T_robot_sensor * model::T_sensor_optical()
                                           : mount->T_robot_sensor;
    cloud = model::transform_cloud(cloud, T_robot_cloud);
  }
  const filters::PipelineTiming timing = [&] {
    try {
      return filters::time_pipeline(pipeline, cloud, options.repeat);
    } catch (const model::InputError& error) {  // a stage refused this cloud: name it
      throw error.in_file(path);
    }
  }();
  report::FilterCloudReport report{path,
                                   read.format,
                                   cloud.size(),
                                   read.dropped_non_finite,
                                   read.ignored_fields,
                                   timing.stages,
                                   timing.result.size(),
                                   timing.total,
                                   std::nullopt,
                                   ""};
  if (mode != nullptr) {
    report.load = report::CloudLoad{
        mount->id, mode->frequency,
        filters::pipeline_load(timing, pipeline, static_cast<double>(cloud.size()),
                               mode->frequency)};
  }
  if (!options.out.empty()) {
    io::prepare_output_folder(options.out, "--out");
    report.output = options.out + "/" + std::filesystem::path(path).stem().string() + "_" +
                    pipeline.name + ".pcd";
    io::write_cloud(report.output, timing.result, io::CloudEncoding::binary);
  }
  return report;
}

int run_filter(const FilterOptions& options, std::ostream& out, std::ostream& err) {
  require_option(options.repeat >= 1 && options.repeat <= 10000, "--repeat", "is out of range",
                 "1 to 10000 runs");
  if (!options.out.empty()) io::prepare_output_folder(options.out, "--out");
  model::Pipeline pipeline = pipeline_named(options.pipeline);
  if (options.threads != 0) {
    require_option(options.threads >= 1 && options.threads <= model::kMaxFilterThreads, "--threads",
                   "is out of range",
                   "1 to " + std::to_string(model::kMaxFilterThreads) + " threads");
    pipeline = filters::with_threads(pipeline, options.threads);
  }
  if (!options.scene.empty()) {
    require_option(!options.rig.empty() && options.clouds.empty(), "--scene",
                   "needs --rig and no --cloud", "--rig RIG --scene NAME [--frames N]");
    return run_filter_on_scene(options, pipeline, out, err);
  }
  require_option(!options.clouds.empty(), "--cloud", "is missing",
                 "--cloud FILE..., or --rig RIG --scene NAME");
  require_option(options.write_loads.empty(), "--write-loads", "needs --scene",
                 "--rig RIG --scene NAME --write-loads FILE: loads are measured on every mount's "
                 "simulated frames");
  require_option(options.rig.empty() == options.mount.empty(), "--mount",
                 "needs --rig (and --rig needs --mount)", "--rig RIG --mount ID together");
  std::optional<RigInputs> rig;
  const model::Mount* mount = nullptr;
  const model::SensorMode* mode = nullptr;
  if (!options.rig.empty()) {
    rig = load_rig_inputs(options.rig, "", "");
    for (const model::Mount& candidate : rig->rig.mounts) {
      if (candidate.id == options.mount) mount = &candidate;
    }
    require_option(mount != nullptr, "--mount",
                   "'" + options.mount + "' is not a mount of " + options.rig,
                   "a mount id of the rig");
    mode = rig->library.find(mount->sensor_id)->find_mode(mount->mode_id);
  }
  report::FilterCloudsReport report{pipeline.name, options.repeat, {}, 0.0};
  for (const std::string& path : options.clouds) {
    report.clouds.push_back(filter_cloud(path, options, pipeline, mount, mode));
  }
  report.peak_memory_mib = peak_memory_mib();
  if (options.json) {
    out << report::filter_clouds_json(report).dump(2) << '\n';
  } else {
    report::print_filter_clouds(report, out);
  }
  return kOk;
}

}  // namespace

Command setup_filter(CLI::App& parent) {
  auto options = std::make_shared<FilterOptions>();
  CLI::App* app =
      parent.add_subcommand("filter", "Run a point-cloud filter pipeline and time each stage");
  app->add_option("--cloud", options->clouds, "PCD or PLY clouds");
  app->add_option("--scene", options->scene,
                  "Simulate the --rig's sensors in this scene instead of --cloud");
  app->add_option("--frames", options->frames,
                  "Simulated frames per sensor with --scene (default 20)");
  add_seed_option(*app, options->seed, "the simulated scene and noise (default 1)");
  app->add_option("--pipeline", options->pipeline,
                  "P1, P2, P3, P4, P2_paper2 or a pipeline YAML file (default P4)");
  // The rig whose mount recorded the clouds; optional, as --cloud needs none.
  add_rig_option(*app, options->rig)->required(false);
  app->add_option("--mount", options->mount,
                  "Mount id in --rig: moves the clouds into the robot frame");
  app->add_option(
         "--frame", options->frame,
         "Frame the clouds are in (with --mount): auto (default: optical for a camera, sensor for "
         "a lidar, as drivers publish them), optical, sensor or robot")
      ->check(CLI::IsMember({"auto", "optical", "sensor", "robot"}));
  app->add_option("--repeat", options->repeat,
                  "Runs per cloud for the timing statistics (default 10)");
  app->add_option("--threads", options->threads,
                  "Threads for the neighbour search of every statistical_outlier stage "
                  "(default: the pipeline's, 1; the output is the same for any count)");
  app->add_option("--out", options->out, "Write the filtered clouds (binary PCD) here");
  app->add_option(
      "--write-loads", options->write_loads,
      "With --scene: write each sensor's measured load to this file (catalogs read it)");
  add_format_option(*app, options->json);
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_filter(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
