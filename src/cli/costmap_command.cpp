// `rigdesign costmap --rig RIG --scenario NAME [--layer obstacle|voxel] [--no-hit-layer]
// [--no-memory] [--compare]`: drives the rig's robot through a scenario with the costmap in
// the loop (issue 6 item 3), prints the outcome and the per-update times, and writes costmap frames
// (PNG), the final grids as map_server PGM + YAML and a summary JSON.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <span>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "costmap_variants.hpp"
#include "inputs.hpp"
#include "number_checks.hpp"
#include "progress_line.hpp"
#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/footprint_collision.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/geometry/footprint_hull.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/filtering_loads_io.hpp"
#include "rigdesign/io/maps/map_files.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/io/scene/scenario_file_loader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/idle_cores.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/costmap_frame.hpp"
#include "rigdesign/report/costmap_run_report.hpp"
#include "rigdesign/report/text_table.hpp"
#include "rigdesign/scenarios/floor_ahead.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"

namespace rigdesign::cli {
namespace {

// An update rate above the follower's control rate would update between its commands, one
// below min_update_rate() leaves the robot blind for minutes (scenarios::check_scenario_inputs
// holds the same rules).
double control_rate() {
  const scenarios::ScenarioParams defaults;
  return defaults.control_rate;
}
double min_update_rate() {
  const scenarios::ScenarioParams defaults;
  return defaults.min_update_rate();
}

struct CostmapOptions {
  std::string rig;
  std::string sensors;
  std::string scenario;
  std::string params;                // nav2 costmap parameter file
  double global_frame_height = 0.0;  // [m] of the file's global frame above the floor
  std::string layer;  // empty: the parameters' layer (the scenario's default: obstacle)
  bool no_hit_layer = false;
  bool no_memory = false;  // neither the Hit Layer nor any source's observation_persistence
  bool compare = false;
  std::optional<double> resolution;  // unset: the parameters' (the scenario's default: 0.05 m)
  std::optional<double> window;
  double speed = 0.4;
  double update_rate = 5.0;
  int frame_every = 5;
  std::uint64_t seed = 1;
  std::string out;
  std::string filtering_loads;                 // measured seconds per point (filter --write-loads)
  std::string local_planner = "pure-pursuit";  // or dwa
  bool full_rays = false;                      // every ray of every sensor, no decimation
  double clearance_margin = 0.0;               // [m] footprint padding where the costmap inflates
  std::optional<double> radius_outlier;        // [m] paper 2's stage on camera frames
  int radius_outlier_min = model::RadiusOutlierParams{}.min_neighbours;
  bool no_depth_matching = false;  // every camera ray its own first hit
  bool variants = false;           // paper 2's Table 1 over the rig's mount subsets
  int seeds = 20;
  std::vector<double> margins = scenarios::SweepSettings{}.margins;
};

struct Variant {
  costmap::ObstacleLayerKind layer = costmap::ObstacleLayerKind::obstacle;
  bool hit_layer = true;
  bool persistence = false;  // the sources keep their clouds as the parameters say
  std::string layer_name() const {
    return std::string(model::name_in(costmap::kObstacleLayerNames, layer));
  }
  std::string name() const {
    return layer_name() + (persistence ? "_persistence" : "") + (hit_layer ? "_hit" : "_no_hit");
  }
  std::string label() const {
    const std::string layer_name(model::name_in(costmap::kObstacleLayerNames, layer));
    if (!persistence) return layer_name + (hit_layer ? " + Hit Layer" : ", no memory");
    return layer_name + " + observation persistence" + (hit_layer ? " + Hit Layer" : "");
  }
};

// Whether any source the run uses keeps its clouds (nav2's observation_persistence).
bool any_persistence(const model::Rig& rig, const scenarios::ScenarioParams& params) {
  const std::vector<costmap::ObservationSource> sources = scenarios::mount_sources_of(rig, params);
  return std::any_of(sources.begin(), sources.end(), [](const costmap::ObservationSource& s) {
    return s.observation_persistence > 0.0;
  });
}

void forget_persistence(scenarios::ScenarioParams& params) {
  params.source.observation_persistence = 0.0;
  for (costmap::NamedObservationSource& named : params.mount_sources)
    named.source.observation_persistence = 0.0;
}

// What the report says about every run of this command.
report::CostmapContext context_of(const CostmapOptions& options, const model::Rig& rig) {
  report::CostmapContext context{rig.name, {}, options.scenario, options.seed};
  for (const model::Mount& mount : rig.mounts) context.mount_ids.push_back(mount.id);
  return context;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

report::CostmapRun run_variant(std::ostream& err, const CostmapOptions& options,
                               const RigInputs& inputs,
                               const scenarios::ScenarioDefinition& scenario,
                               const Variant& variant, const std::string& folder,
                               scenarios::ScenarioParams params) {
  params.costmap.layer = variant.layer;
  params.costmap.use_hit_layer = variant.hit_layer;
  if (!variant.persistence) forget_persistence(params);
  report::CostmapRun run{variant.label(),
                         variant.layer_name(),
                         variant.hit_layer,
                         variant.persistence,
                         params,
                         {},
                         folder,
                         0};
  io::prepare_output_folder(folder + "/frames", "--out");
  const costmap::HeightBand band{params.ground_clearance, inputs.rig.body.height};
  std::vector<model::TriangleMesh> moved;
  costmap::CostGrid last_master;
  costmap::CostGrid last_obstacles;
  render::CostmapFrame frame;
  // The body's real outline in the frames (a prism's footprint or a description's parts).
  if (!inputs.rig.body.footprint.empty() || inputs.rig.body.has_parts())
    frame.footprint = geometry::footprint_hull(inputs.rig.body);
  std::vector<model::Vec2> trail;
  const auto outlines_at = [&](std::span<const double> clocks) {
    std::vector<costmap::NamedMesh> meshes;
    for (const model::SceneObject& object : scenario.scene.objects)
      meshes.push_back({object.name, &object.mesh});
    moved.clear();
    for (std::size_t i = 0; i < scenario.scene.moving.size(); ++i) {
      const model::MovingObject& object = scenario.scene.moving[i];
      moved.emplace_back().append(object.mesh,
                                  object.T_world_object(i < clocks.size() ? clocks[i] : 0.0));
    }
    for (std::size_t i = 0; i < moved.size(); ++i)
      meshes.push_back({scenario.scene.moving[i].name, &moved[i]});
    return costmap::FootprintCollisionChecker(meshes, band).outlines();
  };
  const std::vector<std::vector<model::Vec2>> still_outlines = outlines_at({});
  const std::string title = inputs.rig.name + ", " + options.scenario + ", " + variant.label();
  std::vector<double> marking_ranges;
  for (const costmap::ObservationSource& source : scenarios::mount_sources_of(inputs.rig, params))
    marking_ranges.push_back(source.obstacle_max_range);
  ProgressLine progress(err, "costmap: " + variant.label(), "s simulated (at most)");
  run.result = scenarios::run_scenario(
      scenario, inputs.rig, inputs.library, params, [&](const scenarios::ScenarioStep& step) {
        progress.update(std::round(step.time * 10) / 10, scenario.max_duration);
        trail.push_back(step.pose.position);
        last_master = step.costmap->master();
        last_obstacles = step.costmap->obstacle_grid();
        frame.title = title + ", t = " + report::fixed(step.time, 1) + " s";
        frame.remembered = costmap::remembered_cells(*step.costmap);
        frame.obstacles =
            scenario.scene.moving.empty() ? still_outlines : outlines_at(step.object_clocks);
        frame.fovs = render::fov_wedges(inputs.rig, inputs.library, step.pose, marking_ranges);
        frame.path = step.path->waypoints_world;
        frame.trail = trail;
        frame.robot = step.pose.position;
        frame.yaw = step.pose.yaw;
        frame.robot_radius = inputs.rig.body.radius;
        if (options.frame_every > 0 && step.index % options.frame_every == 0) {
          frame.master = &last_master;
          char name[32];
          std::snprintf(name, sizeof name, "frame_%04d.png", step.index);
          render::draw_costmap_frame(frame, folder + "/frames/" + name);
          ++run.frames;
        }
      });
  // The last picture shows where the run ended: the collision pose or the goal.
  const scenarios::TrajectorySample& last = run.result.trajectory.back();
  frame.master = &last_master;
  frame.robot = run.result.collided ? run.result.collision_position : last.pose.position;
  frame.yaw = last.pose.yaw;
  frame.collided = run.result.collided;
  frame.trail.push_back(frame.robot);
  frame.title = title + ": " + (run.result.collided ? "collision" : "no collision");
  render::draw_costmap_frame(frame, folder + "/final.png");
  render::draw_costmap_frame(frame, folder + "/final.svg");
  io::write_map_files(io::to_occupancy_map(last_master), folder + "/master.yaml");
  io::write_map_files(io::to_occupancy_map(last_obstacles), folder + "/obstacles.yaml");
  io::write_file_atomically(
      folder + "/summary.json",
      report::costmap_run_json(context_of(options, inputs.rig), run).dump(2) + "\n");
  return run;
}

// A nav2 parameter file: its costmap, and its observation sources for the mounts they name.
// Returns where the file sets the window, for the simulation's size check.
model::SourceLocation apply_params_file(const std::string& path, double global_frame_height,
                                        const model::Rig& rig, scenarios::ScenarioParams& params) {
  const deploy::CostmapParamsFile file =
      deploy::load_costmap_params(path, params.costmap, params.source, global_frame_height);
  params.costmap = file.costmap;
  params.mount_sources = file.sources;
  for (const costmap::NamedObservationSource& named : file.sources) {
    require_option(rig.find_mount(named.name) != nullptr, "--params",
                   path + ": observation source '" + named.name + "' names no mount of " + rig.file,
                   "observation sources named after the rig's mount ids");
  }
  return file.window_where;
}

// The sources that keep their clouds, as "; observation_persistence left 5.8 s, ...".
std::string persistence_text(const model::Rig& rig, const scenarios::ScenarioParams& params) {
  const std::vector<costmap::ObservationSource> sources = scenarios::mount_sources_of(rig, params);
  std::string text;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (!(sources[i].observation_persistence > 0.0)) continue;
    text += (text.empty() ? "; observation_persistence " : ", ") + rig.mounts[i].id + " " +
            model::format_number(sources[i].observation_persistence, 3) + " s";
  }
  return text;
}

// Each mount's rate and latency as the runs sense them (phase 0), in rig order.
std::vector<scenarios::MountTiming> timings_of(const RigInputs& inputs,
                                               const scenarios::ScenarioParams& params) {
  std::vector<scenarios::MountTiming> timings;
  for (const model::Mount& mount : inputs.rig.mounts) {
    const model::SensorMode& mode = inputs.library.resolved_mode(mount.sensor_id, mount.mode_id);
    timings.push_back(
        scenarios::mount_timing(mount, mode, params.seconds_per_point(mount.sensor_id), 0.0));
  }
  return timings;
}

// The closed-loop reading of "see the floor ahead": how far the rig sees the floor in its
// path, and the speed from which it can stop for a drop first seen there.
void print_floor_ahead(std::ostream& out, const RigInputs& inputs,
                       const scenarios::ScenarioParams& params) {
  const double deceleration = inputs.requirements ? inputs.requirements->braking_deceleration()
                                                  : model::kDefaultDeceleration;
  const scenarios::FloorAhead floor =
      scenarios::floor_ahead(inputs.rig, inputs.library, timings_of(inputs, params),
                             1.0 / params.update_rate, 1.0 / params.control_rate, deceleration);
  if (floor.mount.empty()) {
    out << "  drops: no mount sees the floor ahead within the body's width, so no drop is ever "
           "marked: the robot would drive off one at any speed\n";
    return;
  }
  out << "  drops: " << floor.mount << " sees the floor to " << report::fixed(floor.distance, 2)
      << " m ahead; seen there, a drop stops the robot from up to "
      << report::fixed(floor.stoppable_speed, 2) << " m/s (reaction "
      << report::fixed(floor.reaction, 3)
      << " s: frame period + latency + costmap update + control step; "
      << model::format_number(deceleration) << " m/s^2 braking)"
      << (floor.stoppable_speed < params.follower.speed ? "; slower than the run's speed" : "")
      << "\n";
}

// Each mount's rate and latency as the run senses them, and the rays it casts.
// What a camera's frames go through before the costmap: its depth matching window (a thin
// object at range vanishes) and paper 2's radius outlier removal.
std::string camera_stages_text(const RigInputs& inputs, const model::Mount& mount,
                               const scenarios::ScenarioParams& params) {
  const model::SensorMode* mode = &inputs.library.resolved_mode(mount.sensor_id, mount.mode_id);
  if (!mode->is_camera()) return "";
  std::string text;
  if (mode->depth_matching) {
    const model::DepthMatching& matching = *mode->depth_matching;
    text += params.depth_matching
                ? "; depth from a " + std::to_string(matching.window_px) + "-px window (" +
                      model::format_number(model::rad_to_deg(matching.window_angle), 2) +
                      " deg): what fills under half of it at its range is lost"
                : "; depth matching off (--no-depth-matching)";
  }
  if (params.camera_radius_outlier) {
    text += "; radius outlier removal: " +
            std::to_string(params.camera_radius_outlier->min_neighbours) + " neighbours within " +
            model::format_number(params.camera_radius_outlier->radius) + " m (x" +
            std::to_string(params.camera_decimation) + " with the ray stride)";
  }
  return text;
}

void print_sensing(std::ostream& out, const RigInputs& inputs,
                   const scenarios::ScenarioParams& params, const std::string& loads_file) {
  out << "  sensing at each sensor's own rate, frames reaching the costmap after driver + "
         "filter time ("
      << (loads_file.empty()
              ? "filters " + model::format_number(params.filtering_seconds_per_point) +
                    " core-s per point, paper 1's figure"
              : "filters as measured in " + loads_file)
      << "; rays: cameras every " << params.camera_decimation << ", lidars every "
      << params.lidar_decimation
      << (params.camera_decimation == 1 && params.lidar_decimation == 1
              ? " (full patterns)"
              : " (--full-rays casts all)")
      << "):\n";
  const std::vector<scenarios::MountTiming> timings = timings_of(inputs, params);
  for (std::size_t i = 0; i < timings.size(); ++i) {
    const model::Mount& mount = inputs.rig.mounts[i];
    out << "    " << mount.id << ": " << scenarios::describe(timings[i])
        << (mount.throttle_hz ? " (throttled)" : "") << camera_stages_text(inputs, mount, params)
        << "\n";
  }
}

std::string window_text(const costmap::CostmapParams& costmap) {
  if (costmap.size_x == costmap.size_y) return model::format_number(costmap.size_x);
  return model::format_number(costmap.size_x) + " x " + model::format_number(costmap.size_y);
}

// The options no rig is needed to judge.
void check_costmap_options(const CostmapOptions& options, bool from_file) {
  const std::vector<std::string>& names = scenarios::costmap_scenario_names();
  require_option(
      from_file || std::find(names.begin(), names.end(), options.scenario) != names.end(),
      "--scenario", "unknown scenario '" + options.scenario + "'",
      "one of: " + joined(names) + ", or a scenario file ending in .yaml");
  require_option(options.layer.empty() ||
                     model::value_in(costmap::kObstacleLayerNames, options.layer).has_value(),
                 "--layer", "unknown layer '" + options.layer + "'", "obstacle or voxel");
  require_option(!options.resolution || *options.resolution > 0.0, "--resolution",
                 "must be positive", "a cell side > 0 [m]");
  require_option(!options.window || *options.window > 0.0, "--window", "must be positive",
                 "a window side > 0 [m]");
  require_option(options.speed > 0.0, "--speed", "must be positive", "a speed > 0 [m/s]");
  require_option(options.frame_every >= 0, "--frame-every", "must not be negative",
                 "0 (no frames) or a number of updates");
}

// The run's parameters: the nav2 file's, then the options over them (the window checked
// against the robot's footprint). The filtering loads and the scenario's settings come after.
scenarios::ScenarioParams params_from_options(const CostmapOptions& options,
                                              const RigInputs& inputs) {
  scenarios::ScenarioParams params;
  if (!options.params.empty()) {
    params.window_where =
        apply_params_file(options.params, options.global_frame_height, inputs.rig, params);
  }
  if (options.resolution) params.costmap.resolution = *options.resolution;
  if (options.window) params.costmap.size_x = params.costmap.size_y = *options.window;
  if (options.resolution || options.window) params.window_where = model::SourceLocation();
  if (params.window_where.file.empty()) params.window_where.file = "(command line)";
  const double footprint = 2.0 * inputs.rig.body.radius;
  require_option(
      std::min(params.costmap.size_x, params.costmap.size_y) >= footprint, "--window",
      "is smaller than the robot's footprint (" + model::format_number(footprint) + " m across)",
      "a window side >= " + model::format_number(footprint) + " m");
  params.follower.speed = options.speed;
  params.update_rate = options.update_rate;
  params.seed = options.seed;
  return params;
}

// The planner, the rays and the margin, as the options ask.
void apply_driving_options(const CostmapOptions& options, scenarios::ScenarioParams& params) {
  if (options.full_rays) params.camera_decimation = params.lidar_decimation = 1;
  require_option(options.local_planner == "pure-pursuit" || options.local_planner == "dwa",
                 "--local-planner", "is '" + options.local_planner + "'", "pure-pursuit or dwa");
  if (options.local_planner == "dwa") params.local_planner = scenarios::LocalPlanner::dwa;
  params.clearance_margin = options.clearance_margin;
  if (options.radius_outlier) {
    params.camera_radius_outlier =
        model::RadiusOutlierParams{*options.radius_outlier, options.radius_outlier_min};
  }
  params.depth_matching = !options.no_depth_matching;
}

// What the run is: the scenario, the grid, the rates, the sensing, the floor ahead, the planner.
void print_setup(std::ostream& out, const CostmapOptions& options, const RigInputs& inputs,
                 const scenarios::ScenarioDefinition& scenario,
                 const scenarios::ScenarioParams& params) {
  out << inputs.rig.name << " in scenario " << scenario.name << " (seed " << options.seed
      << "): " << scenario.description << "\n";
  out << "  " << model::format_number(params.costmap.resolution) << " m cells, "
      << window_text(params.costmap) << " m window, " << model::format_number(options.update_rate)
      << " Hz updates, " << model::format_number(options.speed) << " m/s; "
      << (params.costmap.use_hit_layer
              ? "Hit Layer hit " + std::to_string(params.costmap.hit.hit) + ", hit_max " +
                    std::to_string(params.costmap.hit.hit_max)
              : std::string("no Hit Layer"))
      << persistence_text(inputs.rig, params) << "\n";
  print_sensing(out, inputs, params, options.filtering_loads);
  if (!scenario.drops.empty()) print_floor_ahead(out, inputs, params);
  out << "  local planner: "
      << (params.local_planner == scenarios::LocalPlanner::dwa
              ? "DWA (sim_time " + model::format_number(params.dwa.sim_time) + " s, " +
                    std::to_string(params.dwa.linear_samples) + " x " +
                    std::to_string(params.dwa.angular_samples) + " velocities)"
              : std::string("pure pursuit"))
      << ", Dijkstra global plans at each update\n";
}

// `--variants`: paper 2's Table 1 over the rig's mount subsets.
void run_table1(std::ostream& out, std::ostream& err, const CostmapOptions& options,
                const RigInputs& inputs, const scenarios::ScenarioFactory& make_scenario,
                scenarios::ScenarioParams params, const std::string& folder) {
  require_option(std::is_sorted(options.margins.begin(), options.margins.end()) &&
                     options.margins.front() >= 0.0,
                 "--margins", "must be ascending and not negative", "e.g. 0,0.05,0.1");
  scenarios::SweepSettings settings;
  settings.seeds = options.seeds;
  settings.first_seed = options.seed;
  settings.margins = options.margins;
  settings.threads = 1 + model::idle_cores();
  params.costmap.use_hit_layer =
      params.costmap.use_hit_layer && !options.no_hit_layer && !options.no_memory;
  if (options.no_memory) forget_persistence(params);
  if (!options.layer.empty())
    params.costmap.layer = *model::value_in(costmap::kObstacleLayerNames, options.layer);
  run_costmap_variants(out, err, inputs, make_scenario, params, settings, folder);
}

// The variants to run: the one the options name, or `--compare`'s six (or four).
std::vector<Variant> variants_of(const CostmapOptions& options, const RigInputs& inputs,
                                 const scenarios::ScenarioParams& params) {
  const bool persistence = any_persistence(inputs.rig, params) && !options.no_memory;
  std::vector<Variant> variants;
  if (options.compare) {
    for (costmap::ObstacleLayerKind layer :
         {costmap::ObstacleLayerKind::obstacle, costmap::ObstacleLayerKind::voxel}) {
      // Without any memory first, then the file's persistence, then paper 1's Hit Layer.
      variants.push_back({layer, false, false});
      if (persistence) variants.push_back({layer, false, true});
      variants.push_back({layer, true, false});
    }
  } else {
    const costmap::ObstacleLayerKind layer =
        model::value_in(costmap::kObstacleLayerNames, options.layer).value_or(params.costmap.layer);
    variants.push_back({layer,
                        params.costmap.use_hit_layer && !options.no_hit_layer && !options.no_memory,
                        persistence});
  }
  return variants;
}

// Each variant run, reported, and with `--compare` the table and comparison.json.
void run_and_report(std::ostream& out, std::ostream& err, const CostmapOptions& options,
                    const RigInputs& inputs, const scenarios::ScenarioDefinition& scenario,
                    const scenarios::ScenarioParams& params, const std::string& folder) {
  std::vector<report::CostmapRun> runs;
  nlohmann::json all = nlohmann::json::array();
  for (const Variant& variant : variants_of(options, inputs, params)) {
    const std::string variant_folder = options.compare ? folder + "/" + variant.name() : folder;
    runs.push_back(run_variant(err, options, inputs, scenario, variant, variant_folder, params));
    report::print_costmap_run(runs.back(), out);
    all.push_back(report::costmap_run_json(context_of(options, inputs.rig), runs.back()));
  }
  if (options.compare) {
    out << "comparison:\n";
    report::print_costmap_comparison(runs, out);
    io::write_file_atomically(folder + "/comparison.json", all.dump(2) + "\n");
    out << "  wrote " << folder << "/comparison.json\n";
  }
}

int run_costmap(const CostmapOptions& options, std::ostream& out, std::ostream& err) {
  const bool from_file = io::is_scenario_file(options.scenario);
  check_costmap_options(options, from_file);
  const RigInputs inputs = load_rig_inputs(options.rig, options.sensors, "", &err);
  scenarios::ScenarioParams params = params_from_options(options, inputs);
  model::FilteringLoads loads;
  if (!options.filtering_loads.empty()) {
    loads = io::load_filtering_loads(options.filtering_loads);
    params.filtering_loads = &loads;
  }
  apply_driving_options(options, params);
  // A scenario file is read once; a bundled one is laid out for each seed and the body.
  std::optional<scenarios::ScenarioDefinition> from_disk;
  if (from_file) from_disk = io::load_scenario_file(options.scenario);
  const scenarios::ScenarioFactory make_scenario = [&](std::uint64_t seed, double radius) {
    return from_disk ? *from_disk
                     : scenarios::make_costmap_scenario(options.scenario, seed, radius);
  };
  const scenarios::ScenarioDefinition scenario =
      make_scenario(options.seed, inputs.rig.body.radius);
  scenarios::apply_scenario_settings(scenario, params);
  if (options.full_rays) params.camera_decimation = params.lidar_decimation = 1;
  scenarios::check_scenario_inputs(inputs.rig, inputs.library, params);
  // A file's stem names its default folder ("lab_goals.scenario"), never a path inside it.
  const std::string folder =
      !options.out.empty()
          ? options.out
          : "costmap/" + (from_file ? std::filesystem::path(options.scenario).stem().string()
                                    : options.scenario);
  io::prepare_output_folder(folder, "--out");
  print_setup(out, options, inputs, scenario, params);
  if (options.variants) {
    run_table1(out, err, options, inputs, make_scenario, params, folder);
  } else {
    run_and_report(out, err, options, inputs, scenario, params, folder);
  }
  return kOk;
}

// The costmap's grid, the driving speed and the update and frame rates.
void add_grid_and_driving_options(CLI::App* app, CostmapOptions& options) {
  app->add_option("--resolution", options.resolution, "Cell side [m] (default 0.05)")
      ->check(positive_up_to(1.0, "a cell side in (0, 1] m"));
  app->add_option("--window", options.window, "Rolling window side [m] (default 6)")
      ->check(positive_up_to(100.0, "a window side in (0, 100] m"));
  app->add_option("--speed", options.speed, "Driving speed [m/s] (default 0.4)")
      ->check(positive_up_to(10.0, "a speed in (0, 10] m/s"));
  app->add_option("--update-rate", options.update_rate,
                  "Sensing, costmap and planning rate [Hz] (default 5)")
      ->check(finite_in(min_update_rate(), control_rate(),
                        "a rate in [" + model::format_number(min_update_rate(), 3) + ", " +
                            model::format_number(control_rate()) +
                            "] Hz (an update a minute up to the follower's control rate)"));
  app->add_option("--frame-every", options.frame_every,
                  "Write a PNG frame every N updates (default 5, 0: none)")
      ->check(finite_in(0, 100000, "0 (none) or an update count"));
}

// `--variants`: paper 2's Table 1 over the rig's mount subsets.
void add_table1_options(CLI::App* app, CostmapOptions& options) {
  app->add_flag("--variants", options.variants,
                "Paper 2's Table 1: run the whole rig, every subset without one mount and each "
                "mount alone, --seeds seeds each, at the smallest --margins margin without a "
                "collision (the critical distance), and print them beside paper 2's numbers");
  app->add_option("--seeds", options.seeds,
                  "Seeds per variant and margin, from --seed (default 20)")
      ->check(finite_in(1, 1000, "a count from 1 to 1000"));
  app->add_option("--margins", options.margins,
                  "Clearance margins [m] the critical-distance sweep tries, ascending "
                  "(default 0,0.05,...,0.3)")
      ->delimiter(',')
      ->check(finite_in(0.0, 2.0, "margins in [0, 2] m"));
}

}  // namespace

Command setup_costmap(CLI::App& parent) {
  auto options = std::make_shared<CostmapOptions>();
  CLI::App* app = parent.add_subcommand("costmap",
                                        "Drive the rig's robot through a scenario with the "
                                        "costmap, planner and follower in the loop");
  add_rig_option(*app, options->rig);
  add_sensors_option(*app, options->sensors);
  app->add_option("--scenario", options->scenario,
                  "wall_following, stationary, office_goals, or a scenario file (FILE.yaml: "
                  "docs/costmap_scenarios.md)")
      ->required();
  app->add_option("--params", options->params,
                  "nav2 costmap parameter file (docs/costmap.md); options below override it");
  app->add_option("--global-frame-height", options->global_frame_height,
                  "Height [m] of the --params file's global frame above the floor, as export "
                  "--global-frame-height wrote it (default 0)")
      ->check(finite_in(-10.0, 10.0, "a height in metres within +-10"));
  app->add_option("--layer", options->layer,
                  "obstacle (2D) or voxel (3D) (default: the parameters', else obstacle)");
  app->add_flag("--no-hit-layer", options->no_hit_layer, "Run without paper 1's Hit Layer");
  app->add_flag("--no-memory", options->no_memory,
                "Run without any blind-gap memory: no Hit Layer, no source keeps its clouds "
                "(observation_persistence 0)");
  app->add_flag("--compare", options->compare,
                "Run both layers without memory, with the parameters' observation persistence "
                "(if any) and with the Hit Layer, and print a table");
  add_grid_and_driving_options(app, *options);
  add_seed_option(*app, options->seed,
                  "the scene, the sensor noise and the sensors' frame phases (default 1)");
  app->add_option("--filtering-loads", options->filtering_loads,
                  "Measured filtering cost per point (rigdesign filter --write-loads): the "
                  "filters' share of each frame's latency (default paper 1's 3.5e-7 core-s)");
  app->add_option("--local-planner", options->local_planner,
                  "pure-pursuit (default) or dwa: paper 2's Dynamic Window Approach with "
                  "dwa_local_planner's defaults")
      ->capture_default_str();
  app->add_flag("--full-rays", options->full_rays,
                "Cast every ray of every sensor (default: every 8th camera pixel row and "
                "column, every 4th lidar ray along the scan)");
  app->add_option("--clearance-margin", options->clearance_margin,
                  "Footprint padding [m] where the costmap inflates: how close the planners let "
                  "the robot come to what its sensors see (default 0)")
      ->check(finite_in(0.0, 2.0, "a margin in [0, 2] m"));
  app->add_option("--radius-outlier", options->radius_outlier,
                  "Paper 2's radius outlier removal on every camera frame before the costmap: "
                  "points with fewer than --radius-outlier-min others within this radius [m] go "
                  "(scaled by the camera ray stride; default: off)")
      ->check(finite_in(1e-3, 1.0, "a radius in [0.001, 1] m"));
  app->add_option("--radius-outlier-min", options->radius_outlier_min,
                  "Neighbours a point needs to stay under --radius-outlier (default 2)")
      ->check(CLI::Range(1, 1000).description("a count from 1 to 1000"));
  app->add_flag("--no-depth-matching", options->no_depth_matching,
                "Every camera ray returns its own first hit (default: a camera with "
                "depth_matching in its datasheet reports the depth filling most of each "
                "pixel's window, so thin objects at range vanish)");
  add_table1_options(app, *options);
  add_out_option(*app, options->out, "frames, grids and the summary (default costmap/<scenario>)");
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_costmap(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
