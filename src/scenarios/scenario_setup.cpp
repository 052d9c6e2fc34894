#include "scenarios/scenario_setup.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/sim/decimation.hpp"
#include "rigdesign/sim/noise_stream.hpp"
#include "rigdesign/sim/robot_occlusion.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

namespace rigdesign::scenarios::detail {
namespace {

// Stream ids of the frame phases: far from the mounts' noise streams (0, 1, ...).
constexpr std::uint64_t kPhaseStream = 1u << 20;

// Mount i's first capture: given, else uniform over its period from the seed.
double frame_phase(const ScenarioParams& params, std::size_t i, const model::SensorMode& mode,
                   const model::Mount& mount) {
  if (i < params.frame_phases.size()) return params.frame_phases[i];
  const double rate = std::min(mode.frequency, mount.throttle_hz.value_or(mode.frequency));
  std::mt19937_64 stream = sim::noise_stream(params.seed, kPhaseStream + i);
  return std::uniform_real_distribution<double>(0.0, 1.0 / rate)(stream);
}

}  // namespace

Setup make_setup(const model::Rig& rig, const model::SensorLibrary& library,
                 const ScenarioParams& params) {
  Setup setup;
  setup.costmap = params.costmap;
  const double radius = rig.body.radius + std::max(0.0, params.clearance_margin);
  setup.costmap.robot_radius = radius;
  setup.costmap.inflation.inscribed_radius = radius;
  // nav2 asks for an inflation radius above the inscribed one; 0.1 m keeps a cost gradient.
  setup.costmap.inflation.inflation_radius =
      std::max(setup.costmap.inflation.inflation_radius, radius + 0.1);
  setup.costmap.voxel.z_max =
      std::max(setup.costmap.voxel.z_min + setup.costmap.voxel.z_resolution, rig.body.height);
  const std::vector<costmap::ObservationSource> sources = mount_sources_of(rig, params);
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::Sensor* sensor = library.find(mount.sensor_id);
    const model::SensorMode* mode = sensor ? sensor->find_mode(mount.mode_id) : nullptr;
    if (!mode) continue;
    const double per_point = params.seconds_per_point(mount.sensor_id);
    SimulatedMount simulated{
        mount,
        sim::decimated_mode(*mode, params.camera_decimation, params.lidar_decimation),
        {},
        sources[i],
        mount_timing(mount, *mode, per_point, frame_phase(params, i, *mode, mount)),
        {}};
    if (!params.model_latency) simulated.timing.driver = simulated.timing.filtering = 0.0;
    simulated.rays = sim::ray_pattern(simulated.mode);
    simulated.free_ranges =
        sim::robot_free_ranges(rig, library, mount, simulated.mode, simulated.rays);
    setup.mounts.push_back(std::move(simulated));
  }
  return setup;
}

model::Pose3 to_pose3(const costmap::Pose2& pose) {
  model::Pose3 T_world_robot = model::Pose3::Identity();
  T_world_robot.translate(model::Vec3(pose.position.x(), pose.position.y(), 0.0));
  T_world_robot.rotate(Eigen::AngleAxisd(pose.yaw, model::Vec3::UnitZ()));
  return T_world_robot;
}

bool can_mark(const SimulatedMount& mount, const costmap::ObservationSource& source) {
  const double near = std::max(mount.mode.min_range, source.obstacle_min_range);
  const double far = std::min(mount.mode.max_range, source.obstacle_max_range);
  if (near > far) return false;
  const model::Vec3 origin = mount.mount.T_robot_sensor.translation();
  const model::Mat3 R_robot_sensor = mount.mount.T_robot_sensor.linear();
  return std::any_of(mount.rays.begin(), mount.rays.end(), [&](const model::Vec3& ray) {
    const double dz = (R_robot_sensor * ray).z();
    const double z_near = origin.z() + dz * near;
    const double z_far = origin.z() + dz * far;
    return std::max(z_near, z_far) >= source.min_obstacle_height &&
           std::min(z_near, z_far) <= source.max_obstacle_height;
  });
}

}  // namespace rigdesign::scenarios::detail

namespace rigdesign::scenarios {
namespace {

// Cells a simulated costmap window may hold (check_scenario_inputs says why).
constexpr double kMaxSimulatedCells = 1e6;

// Counts a run derives from its rates, judged in floating point before any becomes an integer
// or a loop (issue 53 item 3).
// [Hz] frames per second a mount may record: every frame is ray-cast. The fastest range
// sensors record 50 (2D lidars) to 90 (depth cameras) frames per second; 1 kHz leaves room
// and keeps a frame index of a day-long run far inside a long.
constexpr double kMaxFrameRate = 1000.0;

void check_run_counts(const detail::Setup& setup, const ScenarioParams& params,
                      const model::SourceLocation& where, model::Diagnostics& findings) {
  using model::format_number;
  const double steps = params.control_rate / params.update_rate;
  if (params.update_rate > 0.0 && !(params.update_rate >= params.min_update_rate())) {
    findings.error(where, "update_rate",
                   "is " + format_number(params.update_rate) + " Hz: " + format_number(steps, 4) +
                       " control steps between updates",
                   "at least " + format_number(params.min_update_rate(), 3) +
                       " Hz: an update a minute, at most " +
                       format_number(ScenarioParams::kMaxStepsPerUpdate) + " control steps apart");
  }
  for (const detail::SimulatedMount& mount : setup.mounts) {
    const double rate = 1.0 / mount.timing.period;
    if (rate <= kMaxFrameRate) continue;
    findings.error(mount.mount.sensor_where, "mounts." + mount.mount.id,
                   "records " + format_number(rate, 4) + " frames per second",
                   "a sensor mode (or throttle_hz) of at most 1000 Hz: every frame is simulated");
  }
}

}  // namespace

double ScenarioParams::seconds_per_point(const std::string& sensor_id) const {
  const model::FilteringLoad* measured =
      filtering_loads ? filtering_loads->find(sensor_id) : nullptr;
  return measured ? measured->seconds_per_point : filtering_seconds_per_point;
}

std::vector<costmap::ObservationSource> mount_sources_of(const model::Rig& rig,
                                                         const ScenarioParams& params) {
  std::vector<costmap::ObservationSource> sources;
  for (const model::Mount& mount : rig.mounts) {
    const auto named = std::find_if(params.mount_sources.begin(), params.mount_sources.end(),
                                    [&](const auto& s) { return s.name == mount.id; });
    if (named != params.mount_sources.end()) {
      sources.push_back(named->source);
    } else {
      sources.push_back(params.source);
      // nav2 practice: points above the robot neither mark nor clear.
      sources.back().max_obstacle_height = rig.body.height;
    }
  }
  return sources;
}

void check_scenario_inputs(const model::Rig& rig, const model::SensorLibrary& library,
                           const ScenarioParams& params, const model::SourceLocation& where) {
  model::Diagnostics findings;
  if (!(rig.body.radius > 0.0) || !(rig.body.height > 0.0)) {
    findings.error(rig.where, "body", "needs a positive radius and height for the collision check",
                   "body: {radius: > 0, height: > 0} [m]");
  }
  if (!(params.update_rate > 0.0) || !(params.control_rate >= params.update_rate)) {
    findings.error(where, "update_rate", "must be positive and at most control_rate",
                   "0 < update_rate <= control_rate [Hz]");
  }
  for (const model::Mount& mount : rig.mounts) {
    const model::Sensor* sensor = library.find(mount.sensor_id);
    if (!sensor || !sensor->find_mode(mount.mode_id)) {
      findings.error(mount.sensor_where, "mounts." + mount.id,
                     "names a sensor or mode the sensor library lacks",
                     "a sensor and mode of the library");
    }
  }
  const detail::Setup setup = detail::make_setup(rig, library, params);
  const bool any = std::any_of(setup.mounts.begin(), setup.mounts.end(), [&](const auto& mount) {
    return detail::can_mark(mount, mount.source);
  });
  if (!any) {
    // Every mount without a source of its own shares this one; named sources are the user's.
    costmap::ObservationSource shared = params.source;
    shared.max_obstacle_height = rig.body.height;
    findings.error(rig.where, "mounts",
                   "no sensor can mark the costmap: none sees the height band " +
                       model::format_number(shared.min_obstacle_height) + " to " +
                       model::format_number(shared.max_obstacle_height) + " m within " +
                       model::format_number(shared.obstacle_max_range) + " m",
                   "at least one mount whose rays reach obstacles the body could hit");
  }
  check_run_counts(setup, params, where, findings);
  findings.throw_if_errors();
  costmap::check_costmap_params(setup.costmap, where);
  // The simulation keeps about 1 KB per cell (layers, voxel columns and the frames the
  // figures draw; measured on this machine: a 40 m window at 0.05 m, 640,000 cells, peaked
  // at 0.75 GB and took 20 s; 80 m, 2.6 M cells, 2.8 GB and 76 s). Bounded before allocating.
  const double cells = std::ceil(setup.costmap.size_x / setup.costmap.resolution) *
                       std::ceil(setup.costmap.size_y / setup.costmap.resolution);
  if (cells > kMaxSimulatedCells) {
    throw model::InputError(model::Diagnostic{
        params.window_where.file.empty() ? model::SourceLocation{"(command line)", 0, 0}
                                         : params.window_where,
        "width, height",
        "the window is " + model::format_number(setup.costmap.size_x) + " x " +
            model::format_number(setup.costmap.size_y) + " m at " +
            model::format_number(setup.costmap.resolution) +
            " m: " + model::format_number(cells, 4) + " cells, about " +
            model::format_number(cells * 1e3 / 1e9, 3) + " GB for the simulation",
        "at most 1e6 cells (about 1 GB): a smaller window or coarser cells (nav2's local "
        "costmaps are 3-10 m)"});
  }
}

}  // namespace rigdesign::scenarios
