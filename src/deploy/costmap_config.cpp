#include "rigdesign/deploy/costmap_config.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/deploy/blind_gap_sources.hpp"
#include "rigdesign/deploy/driver_topics.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/geometry/footprint_hull.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/polygon_area.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {
namespace {

// A hull this close to its circumscribed circle's area is given as robot_radius.
constexpr double kRoundShare = 0.9;
// [m] inflation beyond the circumscribed radius: cost falls off over a margin the path
// planner can use to keep clear of walls.
constexpr double kInflationMargin = 0.1;
// nav2's VoxelLayer packs a column into 16 bits.
constexpr int kMaxConfigVoxels = 16;

// The largest height error of a floor return within `range` of a sensor `height` above the
// floor: a return at range D along a ray of elevation e errs by sigma(D) sin e = sigma(D) H / D
// in height, and sigma(D) H / D = H (a / D + b + c D) is largest at an end of [D_min, range].
double floor_height_error(const model::SensorMode& mode, double height, double down_sine,
                          double range) {
  if (!(down_sine > 0.0) || !(height > 0.0)) return 0.0;
  const double nearest = std::max(height / down_sine, mode.min_range);
  if (nearest > range) return 0.0;
  const auto error = [&](double D) { return mode.noise.sigma(D) * height / D; };
  return std::max(error(nearest), error(range));
}

// nav2's footprint: the hull of the body, or a radius when the hull is nearly round.
void set_footprint(const model::RobotBody& body, CostmapConfig& config) {
  const std::vector<model::Vec2> hull = geometry::footprint_hull(body);
  const model::PolygonRadii radii = model::polygon_radii(hull);
  const double outer = radii.circumscribed;
  const bool round = body.footprint.empty() &&
                     (!body.has_parts() || std::abs(model::signed_area(hull)) >=
                                               kRoundShare * std::numbers::pi * outer * outer);
  config.robot_radius = round && !body.has_parts() ? body.radius : outer;
  config.inscribed_radius = round && !body.has_parts() ? body.radius : radii.inscribed;
  if (!round) config.footprint = hull;
  config.notes.push_back(
      round ? "footprint: robot_radius " + model::format_number(config.robot_radius, 4) +
                  " m (the body is round)"
            : "footprint: convex hull of the body, " + std::to_string(hull.size()) +
                  " corners, circumscribed radius " + model::format_number(outer, 4) + " m");
}

}  // namespace

std::string expand_topic(const std::string& text, const std::string& mount_id) {
  std::string expanded = text;
  const std::string key = "{mount}";
  for (std::size_t at = expanded.find(key); at != std::string::npos;
       at = expanded.find(key, at + mount_id.size())) {
    expanded.replace(at, key.size(), mount_id);
  }
  return expanded;
}

CostmapConfig costmap_config(const model::Rig& rig, const model::SensorLibrary& library,
                             const model::Requirements* requirements,
                             const DeployOptions& options) {
  CostmapConfig config;
  config.robot_base_frame = rig.base_link;
  set_footprint(rig.body, config);
  const double top = rig.body.area_top();
  costmap::CostmapParams& p = config.costmap;
  p.resolution = 0.05;  // nav2's default
  // nav2 declares the window's width and height as whole metres (int parameters).
  p.size_x = p.size_y = std::max(3.0, model::round_up(2 * rig.distance_of_interest, 1.0));
  p.robot_radius = config.robot_radius;
  p.inflation.inscribed_radius = config.inscribed_radius;
  config.inflation_margin = kInflationMargin;
  p.inflation.inflation_radius = model::round_up(config.robot_radius + kInflationMargin, 0.01);
  config.update_rate = options.update_rate;
  config.global_frame_height = options.global_frame_height;
  config.floor_noise_sigmas = options.floor_noise_sigmas;
  bool any_3d = false;
  const SensorFrames frames = sensor_frames(rig, library, options.parent);
  const std::vector<DriverTopic> topics = driver_topics(rig, library, options);
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    const model::SensorMode* mode = &library.resolved_mode(mount.sensor_id, mount.mode_id);
    SourceConfig source;
    source.mount_id = mount.id;
    source.laser_scan = mode->fov.shape().is_planar_scan();
    any_3d = any_3d || !source.laser_scan;
    source.raw_topic = topics[m].topic;
    source.topic_note = topics[m].note;
    source.topic = source.raw_topic;
    source.sensor_frame = frames.frames[m].data_frame;
    costmap::ObservationSource& s = source.source;
    const model::Vec3 origin = mount.T_robot_sensor.translation();
    // Far enough to mark every point of the area up to the mount's distance of interest.
    const double reach = std::hypot(rig.distance_for(mount) + origin.head<2>().norm(),
                                    std::max(origin.z(), top - origin.z()));
    s.obstacle_min_range = mode->min_range;
    s.obstacle_max_range = model::round_up(std::min(mode->max_range, reach), 0.01);
    // The near blind zone is neither marked nor cleared: what sits there is remembered.
    s.raytrace_min_range = mode->min_range;
    s.raytrace_max_range =
        model::round_up(std::min(mode->max_range, s.obstacle_max_range + 0.5), 0.01);
    source.floor_height_error = floor_height_error(
        *mode, origin.z(), mode->fov.shape().steepest_down(mount.T_robot_sensor.linear()),
        s.obstacle_max_range);
    s.min_obstacle_height = model::round_up(
        options.floor_flatness + options.floor_noise_sigmas * source.floor_height_error, 0.01);
    s.max_obstacle_height = top;
    if (requirements && requirements->smallest_obstacle &&
        s.min_obstacle_height > *requirements->smallest_obstacle) {
      config.notes.push_back("warning: " + mount.id + " needs min_obstacle_height " +
                             model::format_number(s.min_obstacle_height, 3) +
                             " m to keep its floor noise out, above the smallest obstacle (" +
                             model::format_number(*requirements->smallest_obstacle, 3) + " m)");
    }
    config.sources.push_back(std::move(source));
  }
  p.layer = any_3d ? costmap::ObstacleLayerKind::voxel : costmap::ObstacleLayerKind::obstacle;
  p.voxel.z_min = 0.0;
  p.voxel.z_resolution = std::max(0.05, model::round_up(top / kMaxConfigVoxels, 0.01));
  p.voxel.z_max = std::ceil(top / p.voxel.z_resolution - 1e-9) * p.voxel.z_resolution;
  const double speed =
      options.max_speed > 0.0
          ? options.max_speed
          : (requirements && requirements->robot_speed ? requirements->robot_speed->speed : 0.0);
  if (speed > 0.0) {
    const std::vector<model::SectorRequirement> none;
    const metrics::RigCoverage coverage = metrics::compute_coverage(rig, library, none);
    config.memory =
        blind_memory(coverage, speed, std::min(speed, options.min_speed), options.update_rate);
    p.hit = config.memory.hit;
    if (options.hit_layer_plugin.empty())
      keep_blind_gap_clouds(rig, library, coverage, config, options.stvl);
  } else {
    config.memory.rule = "no robot speed (requirements R5 or --max-speed): paper 1's values";
  }
  p.use_hit_layer = !options.hit_layer_plugin.empty();
  config.hit_layer_class = options.hit_layer_plugin;
  return config;
}

}  // namespace rigdesign::deploy
