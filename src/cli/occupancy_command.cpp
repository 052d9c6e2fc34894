// `rigdesign occupancy --rig RIG --scene cell`: paper 3's occupancy evaluation on the dynamic
// cell (issue 6, item 5). Every configuration of the sweep sees the same simulated frames;
// scores near the person (paper 3), the whole-cell measures paper 3 lacks, per phase, and the
// Pareto plot of F2 against ghost area against time per update.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "inputs.hpp"
#include "number_checks.hpp"
#include "progress_line.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/statistics.hpp"
#include "rigdesign/occupancy/occupancy_evaluation.hpp"
#include "rigdesign/occupancy/occupancy_sweep.hpp"
#include "rigdesign/render/occupancy_pareto.hpp"
#include "rigdesign/report/occupancy_paper3_report.hpp"
#include "rigdesign/report/occupancy_report.hpp"
#include "rigdesign/report/text_table.hpp"
#include "rigdesign/sim/mean_pooling.hpp"
#include "rigdesign/sim/person_links.hpp"
#include "rigdesign/sim/scene_library.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

namespace rigdesign::cli {
namespace {

struct OccupancyOptions {
  std::string rig;
  std::string scene = "cell";
  double rate = 5.0;
  double duration = 96.0;
  double moving_until = 48.0;
  std::vector<double> voxels = occupancy::default_sweep_voxels();
  std::string persistence = "sweep";
  std::string params;  // nav2 costmap parameter file
  int camera_stride = 1;
  int camera_pooling = 1;
  std::uint64_t seed = 1;
  double robot_radius = 0.3;
  // [m] 3 sigma of the cell's noisiest lidars (3 cm): lower, and floor returns mark ghosts.
  double min_height = 0.1;
  std::string truth = "links";             // paper 3's link volumes, the ray re-cast or the mesh
  std::string region = "hull";             // paper 3's convex hull, or the box + object margin
  std::vector<std::string> sweeps;         // paper 3's sweeps; empty: the voxels x persistence grid
  std::string voxblox_occupied = "nodes";  // which voxblox_ros output is the occupied set
  std::string sync = "approximate";        // paper 3's approximate-time fusion, or one instant
  int threads = 2;
  std::string out;
  bool json = false;
};

// "paper" runs the Hit Layer with `hit`: paper 1's values, or a parameter file's.
std::vector<occupancy::PersistenceSetting> persistence_named(const std::string& name,
                                                             const costmap::HitLayerParams& hit) {
  if (name == "none") return {occupancy::PersistenceSetting{}};
  if (name == "paper")
    return {occupancy::PersistenceSetting{},
            occupancy::PersistenceSetting{true, hit.hit, hit.hit_max}};
  return occupancy::default_sweep_persistence();
}

// A nav2 parameter file over the mappers' settings: its Hit Layer, voxel column top, robot
// radius and observation source. The mappers give every sensor one source, so the file's
// sources must agree.
void apply_params_file(const std::string& path, occupancy::VoxelMapperParams& base) {
  costmap::CostmapParams defaults;
  defaults.hit = base.hit;
  defaults.voxel.z_max = base.z_max;
  defaults.robot_radius = base.robot_radius;
  const deploy::CostmapParamsFile file = deploy::load_costmap_params(path, defaults, base.source);
  base.hit = file.costmap.hit;
  base.z_max = file.costmap.voxel.z_max;
  base.robot_radius = file.costmap.robot_radius;
  if (file.sources.empty()) return;
  for (const costmap::NamedObservationSource& named : file.sources) {
    require_option(named.source == file.sources.front().source, "--params",
                   path + ": observation source '" + named.name + "' differs from '" +
                       file.sources.front().name + "'",
                   "one setting for every sensor (the occupancy mappers share one source)");
  }
  base.source = file.sources.front().source;
}

void check_options(const OccupancyOptions& options) {
  require_option(options.rate > 0.0 && options.rate <= 100.0, "--rate", "is out of range",
                 "0 < rate <= 100 Hz");
  require_option(options.duration > 0.0 && options.duration <= 3600.0, "--duration",
                 "is out of range", "0 < duration <= 3600 s");
  require_option(options.moving_until >= 0.0, "--moving-until", "is negative", "a time >= 0 s");
  require_option(
      !options.voxels.empty() && std::all_of(options.voxels.begin(), options.voxels.end(),
                                             [](double v) { return v >= 0.01 && v <= 1.0; }),
      "--voxels", "has a voxel length out of range", "lengths in [0.01, 1] m");
  require_option(options.camera_stride >= 1 && options.camera_stride <= 64, "--camera-stride",
                 "is out of range", "1 to 64");
  require_option(options.min_height >= 0.0 && options.min_height < 1.0, "--min-height",
                 "is out of range", "0 <= height < 1 m");
  require_option(options.robot_radius > 0.0 && options.robot_radius < 2.0, "--robot-radius",
                 "is out of range", "0 < radius < 2 m");
  const auto& names = sim::scene_names();
  require_option(std::find(names.begin(), names.end(), options.scene) != names.end(), "--scene",
                 "unknown scene '" + options.scene + "'", "cell (the scene with a moving person)");
}

// The rig's sensors on the cell; a cone-FOV camera has no pixel grid to pool.
std::vector<occupancy::CellSensor> cell_sensors_for(const OccupancyOptions& options,
                                                    const RigInputs& inputs) {
  std::vector<occupancy::CellSensor> sensors = occupancy::cell_sensors(inputs.rig, inputs.library);
  for (const occupancy::CellSensor& sensor : sensors) {
    require_option(options.camera_pooling == 1 || !sensor.mode.is_camera() ||
                       sim::pixel_grid_columns(sim::ray_pattern(sensor.mode)) > 0,
                   "--camera-pooling",
                   "camera '" + sensor.id + "' has no full pixel grid to pool (a cone FOV)",
                   "1 for a rig with a cone-FOV camera");
  }
  return sensors;
}

occupancy::OccupancyEvalParams evaluation_params(const OccupancyOptions& options) {
  occupancy::OccupancyEvalParams params;
  params.rate = options.rate;
  params.duration = options.duration;
  params.moving_until = options.moving_until;
  params.seed = options.seed;
  params.camera_stride = options.camera_stride;
  params.camera_pooling = options.camera_pooling;
  params.robot_radius = options.robot_radius;
  params.min_height = options.min_height;
  params.truth = options.truth == "surface"  ? occupancy::TruthKind::mesh_surface
                 : options.truth == "points" ? occupancy::TruthKind::sensor_points
                                             : occupancy::TruthKind::link_volumes;
  // The scenes' moving people are all sim's person mesh, whose links these are.
  if (params.truth == occupancy::TruthKind::link_volumes) params.object_links = sim::person_links();
  params.region = options.region == "margin" ? occupancy::ScoringRegion::box_margin
                                             : occupancy::ScoringRegion::hull;
  params.approximate_sync = options.sync == "approximate";
  params.threads = options.threads;
  return params;
}

// Our voxel mapper's settings every row of the grid starts from.
occupancy::VoxelMapperParams base_mapper(const OccupancyOptions& options,
                                         const occupancy::OccupancyEvalParams& params) {
  occupancy::VoxelMapperParams base;
  base.robot_radius = options.robot_radius;
  base.window_size = params.window_size;
  // The whole cell is in reach: every ray clears and marks to its end, as OctoMap's do.
  base.source.obstacle_max_range = base.source.raytrace_max_range = 10.0;
  base.source.min_obstacle_height = options.min_height;
  if (!options.params.empty()) apply_params_file(options.params, base);
  return base;
}

// The mappers one run compares: our grid's, then paper 3's sweeps' (each distinct one once).
struct MapperSet {
  std::vector<occupancy::VoxelMapperParams> grid;
  std::vector<occupancy::Paper3Sweep> sweeps;
  std::vector<std::unique_ptr<occupancy::OccupancyMapper>> owned;
  std::vector<std::string> extra;  // our mappers' names
};

MapperSet make_mappers(const OccupancyOptions& options, const occupancy::VoxelMapperParams& base,
                       const occupancy::OccupancyEvalParams& params,
                       const std::vector<occupancy::CellSensor>& sensors) {
  MapperSet set;
  const std::vector<occupancy::PersistenceSetting> persistence =
      persistence_named(options.persistence, base.hit);
  // Paper 3's sweeps replace the grid by their mappers (each distinct setting once) and our
  // voxel layer at 0.1 m with every persistence setting of the default sweep (none and four
  // Hit Layer settings) as additional rows.
  const std::vector<double> tenth = {0.1};
  set.grid = occupancy::sweep_grid(
      options.sweeps.empty() ? std::span<const double>(options.voxels) : tenth,
      options.sweeps.empty() ? persistence : persistence_named("sweep", base.hit), base);
  set.owned = occupancy::make_sweep_mappers(set.grid, model::SourceLocation{"(command line)"});
  for (const auto& mapper : set.owned) set.extra.push_back(mapper->name());
  set.sweeps = report::paper3_sweeps_named(
      options.sweeps,
      occupancy::Paper3Common{options.min_height, base.z_max, params.window_size,
                              options.voxblox_occupied == "surface"
                                  ? occupancy::VoxbloxOccupiedRule::surface_pointcloud
                                  : occupancy::VoxbloxOccupiedRule::occupied_nodes});
  for (const occupancy::Paper3Sweep& sweep : set.sweeps) {
    for (const occupancy::Paper3Setting& row : sweep.rows) {
      const std::string name = occupancy::paper3_mapper_name(row);
      if (std::none_of(set.owned.begin(), set.owned.end(),
                       [&](const auto& m) { return m->name() == name; }))
        set.owned.push_back(occupancy::make_paper3_mapper(row, sensors));
    }
  }
  return set;
}

// The Pareto front into the report; the files into --out; the report to standard output.
void write_and_print(const OccupancyOptions& options, report::OccupancyReport& report,
                     std::ostream& out) {
  std::vector<render::ParetoPoint> points;
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const occupancy::OccupancyPhase& all = report.runs[i].all;
    points.push_back(
        {report::occupancy_run_label(report, i), all.object.f2, all.ghost_area, all.update_ms});
  }
  for (const std::size_t i : render::pareto_front(points)) report.pareto.push_back(points[i].label);
  if (!options.out.empty()) {
    const std::filesystem::path folder(options.out);
    io::write_file_atomically((folder / "occupancy_frames.csv").string(),
                              report::occupancy_frames_csv(report.runs));
    io::write_file_atomically((folder / "occupancy_summary.json").string(),
                              report::occupancy_json(report).dump(2) + "\n");
    render::plot_occupancy_pareto(points, "Occupancy sweep on the cell: F2 vs ghost area vs time",
                                  (folder / "occupancy_pareto.png").string());
  }
  if (options.json) {
    out << report::occupancy_json(report).dump(2) << '\n';
  } else {
    report::print_occupancy(report, out);
  }
}

int run_occupancy(const OccupancyOptions& options, std::ostream& out, std::ostream& err) {
  check_options(options);
  if (!options.out.empty()) io::prepare_output_folder(options.out, "--out");
  const RigInputs inputs = load_rig_inputs(options.rig, "", "", &err);
  const model::Scene scene = sim::make_scene(options.scene, options.seed);
  require_option(!scene.moving.empty(), "--scene",
                 "'" + options.scene + "' has no moving object to score",
                 "cell (the scene with a moving person)");
  const std::vector<occupancy::CellSensor> sensors = cell_sensors_for(options, inputs);
  occupancy::OccupancyEvalParams params = evaluation_params(options);
  MapperSet set = make_mappers(options, base_mapper(options, params), params, sensors);
  std::vector<occupancy::OccupancyMapper*> mappers;
  for (const auto& mapper : set.owned) mappers.push_back(mapper.get());
  ProgressLine progress(err, "occupancy: " + std::to_string(mappers.size()) + " mapper(s)",
                        "frames");
  params.progress = [&progress](double done, double total) { progress.update(done, total); };
  std::vector<occupancy::OccupancyRun> runs =
      occupancy::evaluate_occupancy(scene, sensors, mappers, params);
  progress.clear();  // the report follows on standard output
  report::OccupancyReport report{
      inputs.rig.name,     options.scene,         sensors.size(),        options.rate,
      options.duration,    options.moving_until,  options.camera_stride, options.camera_pooling,
      params.truth,        params.region,         params.object_margin,  std::move(runs),
      std::move(set.grid), std::move(set.sweeps), std::move(set.extra),  {},
      options.out};
  write_and_print(options, report, out);
  return kOk;
}

// How the cameras are sampled and what the score counts as truth and as a false positive.
void add_sensing_and_scoring_options(CLI::App* app, OccupancyOptions& options) {
  app->add_option("--camera-stride", options.camera_stride,
                  "Keep every n-th camera pixel row and column (default 1)")
      ->check(finite_in(1, 64, "a stride from 1 to 64"));
  app->add_option("--camera-pooling", options.camera_pooling,
                  "Mean-pool each camera's depth image in k x k pixel blocks, as paper 3 "
                  "downsampled its RGB-D camera (default 1: every pixel)")
      ->check(finite_in(1, 16, "a block side from 1 to 16 pixels"));
  app->add_option("--robot-radius", options.robot_radius,
                  "Robot radius for the planner grid's truth [m] (default 0.3)");
  app->add_option(
      "--min-height", options.min_height,
      "Points below this height [m] clear but never mark; truth starts here (default 0.1)");
  // --truth names a ground-truth file elsewhere (localize): here it is what truth is made of.
  CLI::Option* truth_from =
      app->add_option("--truth-from", options.truth,
                      "links: the fused clouds' points inside volumes round the person's links, "
                      "as paper 3 finds them (default); points: the points whose ray ends on "
                      "the person (a noise-free re-cast); surface: the person's whole mesh surface")
          ->check(CLI::IsMember({"links", "points", "surface"}));
  truth_from->excludes(app->add_option("--truth", options.truth, "Former name of --truth-from")
                           ->check(CLI::IsMember({"links", "points", "surface"}))
                           ->group(""));
  app->add_option("--sync", options.sync,
                  "approximate: each sensor at its own rate and phase, fused as ROS's "
                  "approximate-time filter pairs them (paper 3, default); same-instant: every "
                  "sensor records at each frame's time")
      ->check(CLI::IsMember({"approximate", "same-instant"}));
  app->add_option("--fp-region", options.region,
                  "hull: false positives inside the convex hull of the person's truth points "
                  "(paper 3, default); margin: within 0.3 m of the truth's box")
      ->check(CLI::IsMember({"hull", "margin"}));
}

}  // namespace

Command setup_occupancy(CLI::App& parent) {
  auto options = std::make_shared<OccupancyOptions>();
  CLI::App* app =
      parent.add_subcommand("occupancy", "Score occupancy mapping on the dynamic cell (paper 3)");
  app->add_option(
         "rig,--rig", options->rig,
         "Rig of the cell's fixed sensors (its robot frame is the cell frame; positional or --rig)")
      ->required();
  app->add_option("--scene", options->scene, "Scene with a moving person (default cell)");
  app->add_option("--rate", options->rate,
                  "Frames per second; every sensor records each frame (default 5)")
      ->check(positive_up_to(100.0, "a rate in (0, 100] Hz"));
  app->add_option("--duration", options->duration, "Seconds to run (default 96: two laps)")
      ->check(positive_up_to(3600.0, "a duration in (0, 3600] s"));
  app->add_option("--moving-until", options->moving_until,
                  "The robot counts as moving before this time [s], standing after (default 48)")
      ->check(finite_in(0, 3600, "a time in [0, 3600] s"));
  app->add_option("--voxels", options->voxels,
                  "Voxel lengths to sweep [m] (default 0.05 0.1 0.15 0.2)")
      ->check(finite_in(0.01, 1.0, "voxel lengths in [0.01, 1] m"));
  app->add_option("--persistence", options->persistence,
                  "Persistence settings: none, paper or sweep (default)")
      ->check(CLI::IsMember({"none", "paper", "sweep"}));
  app->add_option("--params", options->params,
                  "nav2 costmap parameter file: Hit Layer (for --persistence paper), voxel "
                  "column, robot radius, observation source (docs/costmap.md)");
  add_sensing_and_scoring_options(app, *options);
  std::vector<std::string> sweep_names = occupancy::paper3_sweep_names();
  sweep_names.push_back("paper3");
  app->add_option("--sweep", options->sweeps,
                  "Paper 3's sweeps beside its numbers (repeatable): octomap:resolution|hit|miss, "
                  "skimap:resolution|min_weight, voxblox:resolution|truncation|const_weight, or "
                  "paper3 for all; replaces --voxels/--persistence")
      ->check(CLI::IsMember(sweep_names));
  app->add_option("--voxblox-occupied", options->voxblox_occupied,
                  "Voxblox's occupied set: nodes, its occupied_nodes markers (weight > 1e-3, "
                  "d <= voxel; default); surface, its surface_pointcloud (|d| < 0.75 voxel)")
      ->check(CLI::IsMember({"nodes", "surface"}));
  app->add_option("--threads", options->threads,
                  "Mappers updated at once within a frame (default 2; results do not depend on it)")
      ->check(finite_in(1, 64, "1 to 64 threads"));
  add_seed_option(*app, options->seed, "the range noise (default 1)");
  app->add_option("--out", options->out,
                  "Folder for occupancy_frames.csv, occupancy_summary.json, occupancy_pareto.png "
                  "(default: none, the table on standard output only)");
  add_format_option(*app, options->json);
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_occupancy(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
