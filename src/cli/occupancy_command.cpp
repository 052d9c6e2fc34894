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
#include "occupancy_paper3_report.hpp"
#include "progress_line.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/statistics.hpp"
#include "rigdesign/occupancy/occupancy_evaluation.hpp"
#include "rigdesign/occupancy/occupancy_sweep.hpp"
#include "rigdesign/render/occupancy_pareto.hpp"
#include "rigdesign/sim/mean_pooling.hpp"
#include "rigdesign/sim/scene_library.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"
#include "text_table.hpp"

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
  std::string truth = "points";     // paper 3's sensor points, or the mesh's whole surface
  std::string region = "hull";      // paper 3's convex hull, or the box + object margin
  std::vector<std::string> sweeps;  // paper 3's sweeps; empty: the voxels x persistence grid
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

std::string truth_label(occupancy::TruthKind truth) {
  return truth == occupancy::TruthKind::sensor_points
             ? "the person's points in the sensors' clouds, voxelised (paper 3, III-B)"
             : "the person's whole mesh surface, unseen back included (--truth surface)";
}

std::string region_label(const occupancy::OccupancyEvalParams& params) {
  return params.region == occupancy::ScoringRegion::hull
             ? std::string("inside the convex hull of the person's truth points (paper 3, III-C)")
             : "within " + model::format_number(params.object_margin) +
                   " m of the truth's box (--fp-region margin)";
}

std::string frames_csv(const std::vector<occupancy::OccupancyRun>& runs) {
  std::ostringstream csv;
  csv << "mapper,time_s,robot_moving,points,update_ms,tp,fp,fn,precision,recall,f1,f2,f3,never_"
         "seen,"
         "seen_not_kept,ghost_area_m2,trail_area_m2,trail_length_p90_m,trail_length_oldest_m,"
         "master_precision,master_recall,master_f2,"
         "master_ghost_area_m2\n";
  for (const occupancy::OccupancyRun& run : runs) {
    for (const occupancy::OccupancyFrame& f : run.frames) {
      const occupancy::Scores s = occupancy::scores_of(f.object);
      const occupancy::Scores m = occupancy::scores_of(f.master);
      csv << '"' << run.mapper << "\"," << model::format_number(f.time, 6) << ',' << f.robot_moving
          << ',' << f.points << ',' << model::format_number(f.update_seconds * 1e3, 4) << ','
          << f.object.true_positives << ',' << f.object.false_positives << ','
          << f.object.false_negatives << ',' << model::format_number(s.precision, 4) << ','
          << model::format_number(s.recall, 4) << ',' << model::format_number(s.f1, 4) << ','
          << model::format_number(s.f2, 4) << ',' << model::format_number(s.f3, 4) << ','
          << f.misses.never_seen << ',' << f.misses.seen_not_kept << ','
          << model::format_number(f.ghost_area, 4) << ',' << model::format_number(f.trail_area, 4)
          << ',' << model::format_number(f.trail_length, 4) << ','
          << model::format_number(f.trail_length_oldest, 4) << ','
          << model::format_number(m.precision, 4) << ',' << model::format_number(m.recall, 4) << ','
          << model::format_number(m.f2, 4) << ',' << model::format_number(f.master_ghost_area, 4)
          << '\n';
    }
  }
  return csv.str();
}

nlohmann::json phase_json(const occupancy::OccupancyPhase& phase) {
  const auto value = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  return {{"frames", phase.frames},
          {"person", scores_json(phase.object)},
          {"master", scores_json(phase.master)},
          {"ghost_area_m2", value(phase.ghost_area)},
          {"ghost_area_max_m2", phase.ghost_area_max},
          {"trail_area_m2", value(phase.trail_area)},
          {"trail_length_m", value(phase.trail_length)},
          {"trail_length_max_m", phase.trail_length_max},
          {"master_ghost_area_m2", value(phase.master_ghost_area)},
          {"misses_never_seen", phase.never_seen},
          {"misses_seen_not_kept", phase.seen_not_kept},
          {"mark_delay_median_s", value(model::median(phase.mark_delays))},
          {"mark_delay_p95_s", value(model::percentile(phase.mark_delays, 0.95))},
          {"clear_delay_median_s", value(model::median(phase.clear_delays))},
          {"clear_delay_p95_s", value(model::percentile(phase.clear_delays, 0.95))},
          {"marks", phase.mark_delays.size()},
          {"clears", phase.clear_delays.size()},
          {"update_ms", value(phase.update_ms)},
          {"points_per_second", value(phase.points_per_second)}};
}

void print_tables(const std::vector<occupancy::OccupancyRun>& runs,
                  const std::vector<occupancy::VoxelMapperParams>& grid, std::ostream& out) {
  TextTable scores;
  scores.add_column("voxel m", TextTable::Align::right);
  scores.add_column("persistence", TextTable::Align::left);
  for (const char* h :
       {"P", "R", "F1", "F2", "F3", "P mov", "R mov", "F2 mov", "P still", "R still", "F2 still"}) {
    scores.add_column(h, TextTable::Align::right);
  }
  TextTable cell;
  cell.add_column("voxel m", TextTable::Align::right);
  cell.add_column("persistence", TextTable::Align::left);
  for (const char* h : {"ghost mov m2", "ghost still m2", "trail mov m", "trail still m", "mark s",
                        "clear mov s", "clear still s", "pending", "never seen", "seen lost",
                        "grid F2", "grid ghost m2", "ms/upd", "Mpts/s"}) {
    cell.add_column(h, TextTable::Align::right);
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const occupancy::OccupancyRun& r = runs[i];
    const std::string voxel = fixed(grid[i].voxel, 2),
                      label = occupancy::persistence_label(grid[i]);
    scores.add_row(
        {voxel, label, fixed_or_dash(r.all.object.precision, 3),
         fixed_or_dash(r.all.object.recall, 3), fixed_or_dash(r.all.object.f1, 3),
         fixed_or_dash(r.all.object.f2, 3), fixed_or_dash(r.all.object.f3, 3),
         fixed_or_dash(r.moving.object.precision, 3), fixed_or_dash(r.moving.object.recall, 3),
         fixed_or_dash(r.moving.object.f2, 3), fixed_or_dash(r.stationary.object.precision, 3),
         fixed_or_dash(r.stationary.object.recall, 3), fixed_or_dash(r.stationary.object.f2, 3)});
    const std::size_t misses = r.all.never_seen + r.all.seen_not_kept;
    const auto share = [&](std::size_t n) {
      return misses == 0
                 ? std::string("-")
                 : fixed(100.0 * static_cast<double>(n) / static_cast<double>(misses), 0) + "%";
    };
    cell.add_row(
        {voxel, label, fixed_or_dash(r.moving.ghost_area, 2),
         fixed_or_dash(r.stationary.ghost_area, 2), fixed_or_dash(r.moving.trail_length_max, 2),
         fixed_or_dash(r.stationary.trail_length_max, 2),
         fixed_or_dash(model::median(r.all.mark_delays), 1),
         fixed_or_dash(model::median(r.moving.clear_delays), 1),
         fixed_or_dash(model::median(r.stationary.clear_delays), 1),
         std::to_string(r.pending_changes), share(r.all.never_seen), share(r.all.seen_not_kept),
         fixed_or_dash(r.all.master.f2, 3), fixed_or_dash(r.all.master_ghost_area, 2),
         fixed_or_dash(r.all.update_ms, 1), fixed_or_dash(r.all.points_per_second / 1e6, 2)});
  }
  out << "Near the person (paper 3's score), mean over frames; mov = robot moving, still = "
         "standing\n";
  scores.print(out, "  ");
  out << "\nWhole cell: ghost area and trail (mean / max), median delays, misses by cause, planner "
         "grid\n";
  cell.print(out, "  ");
}

int run_occupancy(const OccupancyOptions& options, std::ostream& out, std::ostream& err) {
  check_options(options);
  if (!options.out.empty()) io::prepare_output_folder(options.out, "--out");
  const RigInputs inputs = load_rig_inputs(options.rig, "", "");
  const model::Scene scene = sim::make_scene(options.scene, options.seed);
  require_option(!scene.moving.empty(), "--scene",
                 "'" + options.scene + "' has no moving object to score",
                 "cell (the scene with a moving person)");
  const std::vector<occupancy::CellSensor> sensors =
      occupancy::cell_sensors(inputs.rig, inputs.library);
  for (const occupancy::CellSensor& sensor : sensors) {
    require_option(options.camera_pooling == 1 || !sensor.mode.is_camera() ||
                       sim::pixel_grid_columns(sim::ray_pattern(sensor.mode)) > 0,
                   "--camera-pooling",
                   "camera '" + sensor.id + "' has no full pixel grid to pool (a cone FOV)",
                   "1 for a rig with a cone-FOV camera");
  }
  occupancy::OccupancyEvalParams params;
  params.rate = options.rate;
  params.duration = options.duration;
  params.moving_until = options.moving_until;
  params.seed = options.seed;
  params.camera_stride = options.camera_stride;
  params.camera_pooling = options.camera_pooling;
  params.robot_radius = options.robot_radius;
  params.min_height = options.min_height;
  params.truth = options.truth == "surface" ? occupancy::TruthKind::mesh_surface
                                            : occupancy::TruthKind::sensor_points;
  params.region = options.region == "margin" ? occupancy::ScoringRegion::box_margin
                                             : occupancy::ScoringRegion::hull;
  occupancy::VoxelMapperParams base;
  base.robot_radius = options.robot_radius;
  base.window_size = params.window_size;
  // The whole cell is in reach: every ray clears and marks to its end, as OctoMap's do.
  base.source.obstacle_max_range = base.source.raytrace_max_range = 10.0;
  base.source.min_obstacle_height = options.min_height;
  if (!options.params.empty()) apply_params_file(options.params, base);
  const std::vector<occupancy::PersistenceSetting> persistence =
      persistence_named(options.persistence, base.hit);
  // Paper 3's sweeps replace the grid by their mappers (each distinct setting once) and our
  // voxel layer at 0.1 m with every persistence setting of the default sweep (none and four
  // Hit Layer settings) as additional rows.
  const std::vector<double> tenth = {0.1};
  const std::vector<occupancy::VoxelMapperParams> grid = occupancy::sweep_grid(
      options.sweeps.empty() ? std::span<const double>(options.voxels) : tenth,
      options.sweeps.empty() ? persistence : persistence_named("sweep", base.hit), base);
  auto owned = occupancy::make_sweep_mappers(grid, model::SourceLocation{"(command line)"});
  std::vector<std::string> extra;
  for (const auto& mapper : owned) extra.push_back(mapper->name());
  const std::vector<occupancy::Paper3Sweep> sweeps = paper3_sweeps_named(
      options.sweeps, occupancy::Paper3Common{options.min_height, base.z_max, params.window_size});
  for (const occupancy::Paper3Sweep& sweep : sweeps) {
    for (const occupancy::Paper3Setting& row : sweep.rows) {
      const std::string name = occupancy::paper3_mapper_name(row);
      if (std::none_of(owned.begin(), owned.end(),
                       [&](const auto& m) { return m->name() == name; }))
        owned.push_back(occupancy::make_paper3_mapper(row, sensors));
    }
  }
  std::vector<occupancy::OccupancyMapper*> mappers;
  for (const auto& mapper : owned) mappers.push_back(mapper.get());
  params.threads = options.threads;
  ProgressLine progress(err, "occupancy: " + std::to_string(mappers.size()) + " mapper(s)",
                        "frames");
  params.progress = [&progress](double done, double total) { progress.update(done, total); };
  const std::vector<occupancy::OccupancyRun> runs =
      occupancy::evaluate_occupancy(scene, sensors, mappers, params);
  progress.clear();  // the report follows on standard output

  std::vector<render::ParetoPoint> points;
  nlohmann::json report = {{"rig", inputs.rig.name},
                           {"scene", options.scene},
                           {"rate_hz", options.rate},
                           {"duration_s", options.duration},
                           {"moving_until_s", options.moving_until},
                           {"camera_stride", options.camera_stride},
                           {"camera_pooling", options.camera_pooling},
                           {"truth", truth_label(params.truth)},
                           {"false_positive_region", region_label(params)},
                           {"runs", nlohmann::json::array()}};
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const bool ours = i < grid.size();
    points.push_back({ours ? model::format_number(grid[i].voxel, 3) + " m, " +
                                 occupancy::persistence_label(grid[i])
                           : runs[i].mapper,
                      runs[i].all.object.f2, runs[i].all.ghost_area, runs[i].all.update_ms});
    report["runs"].push_back({{"mapper", runs[i].mapper},
                              {"voxel_m", runs[i].resolution},
                              {"persistence", ours ? occupancy::persistence_label(grid[i]) : "-"},
                              {"memory_bytes", runs[i].memory_bytes},
                              {"all", phase_json(runs[i].all)},
                              {"moving", phase_json(runs[i].moving)},
                              {"stationary", phase_json(runs[i].stationary)},
                              {"pending_changes", runs[i].pending_changes},
                              {"missed_marks", runs[i].missed_marks},
                              {"missed_clears", runs[i].missed_clears}});
  }
  if (!sweeps.empty()) report["paper3"] = paper3_report_json(sweeps, runs);
  if (!options.out.empty()) {
    const std::filesystem::path folder(options.out);
    io::write_file_atomically((folder / "occupancy_frames.csv").string(), frames_csv(runs));
    io::write_file_atomically((folder / "occupancy_summary.json").string(), report.dump(2) + "\n");
    render::plot_occupancy_pareto(points, "Occupancy sweep on the cell: F2 vs ghost area vs time",
                                  (folder / "occupancy_pareto.png").string());
  }
  if (options.json) {
    out << report.dump(2) << '\n';
    return kOk;
  }
  out << inputs.rig.name << " in the " << options.scene << " scene: " << sensors.size()
      << " sensors, " << runs.front().frames.size() << " frames at "
      << model::format_number(options.rate, 4) << " Hz, robot moving until "
      << model::format_number(options.moving_until, 4) << " s\n"
      << "truth: " << truth_label(params.truth) << "\n"
      << "false positives counted " << region_label(params) << "\n\n";
  if (sweeps.empty()) {
    print_tables(runs, grid, out);
  } else {
    out << "paper 3's sweeps: every setting once, " << runs.size()
        << " mappers on the same frames\n";
    print_paper3_report(sweeps, runs, extra, out);
  }
  out << "\nPareto-optimal (F2 up, ghost area down, ms per update down):";
  for (const std::size_t i : render::pareto_front(points)) out << "\n  " << points[i].label;
  out << '\n';
  if (!options.out.empty()) {
    out << "wrote occupancy_frames.csv, occupancy_summary.json and occupancy_pareto.png to "
        << options.out << '\n';
  }
  return kOk;
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
  app->add_option("--camera-stride", options->camera_stride,
                  "Keep every n-th camera pixel row and column (default 1)")
      ->check(finite_in(1, 64, "a stride from 1 to 64"));
  app->add_option("--camera-pooling", options->camera_pooling,
                  "Mean-pool each camera's depth image in k x k pixel blocks, as paper 3 "
                  "downsampled its RGB-D camera (default 1: every pixel)")
      ->check(finite_in(1, 16, "a block side from 1 to 16 pixels"));
  app->add_option("--robot-radius", options->robot_radius,
                  "Robot radius for the planner grid's truth [m] (default 0.3)");
  app->add_option(
      "--min-height", options->min_height,
      "Points below this height [m] clear but never mark; truth starts here (default 0.1)");
  // --truth names a ground-truth file elsewhere (localize): here it is what truth is made of.
  CLI::Option* truth_from =
      app->add_option("--truth-from", options->truth,
                      "points: the person's points in the sensors' clouds, voxelised (paper 3, "
                      "default); surface: the person's whole mesh surface")
          ->check(CLI::IsMember({"points", "surface"}));
  truth_from->excludes(app->add_option("--truth", options->truth, "Former name of --truth-from")
                           ->check(CLI::IsMember({"points", "surface"}))
                           ->group(""));
  app->add_option("--fp-region", options->region,
                  "hull: false positives inside the convex hull of the person's truth points "
                  "(paper 3, default); margin: within 0.3 m of the truth's box")
      ->check(CLI::IsMember({"hull", "margin"}));
  std::vector<std::string> sweep_names = occupancy::paper3_sweep_names();
  sweep_names.push_back("paper3");
  app->add_option("--sweep", options->sweeps,
                  "Paper 3's sweeps beside its numbers (repeatable): octomap:resolution|hit|miss, "
                  "skimap:resolution|min_weight, voxblox:resolution|truncation|const_weight, or "
                  "paper3 for all; replaces --voxels/--persistence")
      ->check(CLI::IsMember(sweep_names));
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
