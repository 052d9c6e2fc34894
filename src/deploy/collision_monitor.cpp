#include "rigdesign/deploy/collision_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/footprint_hull.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {
namespace {

// A round body's zones use this many sides: a circumscribed polygon holds the circle, and 32
// sides stay within 0.5 % of the radius of it.
constexpr int kRoundSides = 32;

std::string seconds(double value) {
  return model::format_number(value, 3) + " s";
}

std::vector<model::Vec2> outline_corners(const BodyOutline& body) {
  if (!body.hull.empty()) return body.hull;
  const double circumscribed = body.radius / std::cos(std::numbers::pi / kRoundSides);
  std::vector<model::Vec2> corners;
  for (int k = 0; k < kRoundSides; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / kRoundSides;
    corners.emplace_back(circumscribed * std::cos(angle), circumscribed * std::sin(angle));
  }
  return corners;
}

// What the robot sweeps driving straight ahead for `reach` metres: the hull of its outline
// and the outline moved forward.
std::vector<model::Vec2> swept_zone(const BodyOutline& body, double reach) {
  std::vector<model::Vec2> corners = outline_corners(body);
  const std::size_t count = corners.size();
  for (std::size_t i = 0; i < count; ++i) corners.push_back(corners[i] + model::Vec2(reach, 0.0));
  return geometry::convex_hull(corners);
}

CollisionSource collision_source(std::size_t index, const SourceConfig& config,
                                 const model::Mount& mount, const model::SensorMode& mode,
                                 const CollisionMonitorOptions& options) {
  CollisionSource source;
  source.source = index;
  // The frames the stack passes on: the mode's, or the mount's throttle_hz when lower.
  const double frame = 1.0 / std::min(mode.frequency, mount.throttle_hz.value_or(mode.frequency));
  const double processing = options.processing_latency.value_or(frame);
  const double command = 1.0 / kControllerFrequency;
  source.latency = frame + processing + command;
  source.latency_rule =
      "frame period " + seconds(frame) + " + processing " + seconds(processing) +
      (options.processing_latency ? " (--processing-latency)"
                                  : " (one frame period: a chain that keeps up)") +
      " + command period " + seconds(command);
  if (config.laser_scan) {
    source.min_z = 0.0;
    source.max_z = std::numeric_limits<double>::infinity();
  } else {
    source.min_z = config.source.min_obstacle_height;
    source.max_z = config.source.max_obstacle_height;
  }
  return source;
}

// Returns an R6 obstacle gets from the sparsest source that sees the zone, one row counted:
// at the zone's corner farthest from each sensor.
int fewest_returns(const ProtectiveZone& zone, const std::vector<const model::SensorMode*>& modes,
                   const std::vector<model::Vec3>& origins, double size) {
  int fewest = kMinPoints;
  for (const std::size_t s : zone.sources) {
    double farthest = 0.0;
    for (const model::Vec2& p : zone.points) {
      farthest = std::max(farthest, (p - origins[s].head<2>()).norm());
    }
    const double spacing = farthest * modes[s]->angular_resolution_h;
    if (spacing > 0.0) {
      fewest = std::min(fewest, static_cast<int>(std::floor(size / spacing + 1e-9)));
    }
  }
  return fewest;
}

// A protective zone no robot brakes within (a mount throttled to 1e-9 Hz, a deceleration of
// 1e-300 m/s^2) is refused before it is measured: it names the value that made it so.
void refuse_unbounded_zone(const model::Rig& rig, const model::Requirements* requirements,
                           const CollisionMonitor& monitor, double slowdown_reach,
                           const std::string& numbers) {
  if (slowdown_reach <= kMaxZoneReach) return;
  const double v = monitor.speed;
  const bool braking = v * v / (2 * monitor.deceleration) >= v * monitor.latency;
  model::SourceLocation where;
  std::string field = "robot_speed.deceleration";
  if (!braking) {
    field = "the slowest source's frame period";
    for (const CollisionSource& source : monitor.sources) {
      const model::Mount& mount = rig.mounts[source.source];
      if (source.latency == monitor.latency && mount.throttle_hz) {
        where = mount.throttle_where;
        field = "mounts." + mount.id + ".throttle_hz";
      }
    }
  } else if (requirements && requirements->deceleration) {
    where = requirements->deceleration_where;
  }
  throw model::InputError(model::Diagnostic{
      where, field,
      "makes the slowdown zone reach " + model::format_number(slowdown_reach, 3) + " m ahead (" +
          numbers + "): no collision monitor brakes over such a distance",
      "zones within " + model::format_number(kMaxZoneReach, 3) +
          " m: a throttle of a few Hz and a deceleration in m/s^2 (e.g. 0.5 to 3)"});
}

}  // namespace

BodyOutline body_outline(const CostmapConfig& config) {
  BodyOutline outline;
  outline.hull = config.footprint;
  outline.radius = config.robot_radius;
  return outline;
}

std::optional<CollisionMonitor> collision_monitor(const model::Rig& rig,
                                                  const model::SensorLibrary& library,
                                                  const model::Requirements* requirements,
                                                  const CostmapConfig& config,
                                                  const CollisionMonitorOptions& options) {
  const double speed =
      options.speed > 0.0
          ? options.speed
          : (requirements && requirements->robot_speed ? requirements->robot_speed->speed : 0.0);
  if (!(speed > 0.0)) return std::nullopt;
  CollisionMonitor monitor;
  monitor.distro = options.distro;
  monitor.base_frame = config.robot_base_frame;
  monitor.T_robot_base =
      robot_frame_pose(rig, config.robot_base_frame).value_or(model::Pose3::Identity());
  monitor.speed = speed;
  if (requirements && requirements->deceleration) {
    monitor.deceleration = *requirements->deceleration;
    monitor.deceleration_from =
        "robot_speed.deceleration at " + model::to_string(requirements->deceleration_where);
  } else {
    monitor.deceleration = model::kDefaultDeceleration;
    monitor.deceleration_from =
        "not stated (requirements robot_speed.deceleration): nav2 velocity_smoother's default "
        "max_decel, the hardest braking nav2 commands";
  }
  const geometry::BodyOccluder occluder(rig.body);
  std::vector<geometry::MountedFov> fovs;
  fovs.reserve(rig.mounts.size());
  std::vector<const model::SensorMode*> modes;
  std::vector<model::Vec3> origins;
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
    fovs.emplace_back(mode, mount.T_robot_sensor, occluder, mount.housing_link,
                      model::MountLimits{}, geometry::housings_around(rig, library, mount.id));
    modes.push_back(&mode);
    origins.push_back(mount.T_robot_sensor.translation());
    monitor.sources.push_back(collision_source(m, config.sources[m], mount, mode, options));
    monitor.latency = std::max(monitor.latency, monitor.sources.back().latency);
  }
  std::vector<ZoneViewer> viewers;
  for (std::size_t s = 0; s < monitor.sources.size(); ++s) {
    viewers.push_back({&fovs[s], monitor.sources[s].min_z, monitor.sources[s].max_z});
  }
  // Stop: from full speed, react within the slowest source's latency, then brake. Slow down:
  // early enough to brake to the slowdown speed before the stop zone's edge.
  const double v = speed;
  const double a = monitor.deceleration;
  const double t = monitor.latency;
  const double rho = monitor.slowdown_ratio;
  const double stop = model::round_up(v * t + v * v / (2 * a), 0.01);
  const double slow = model::round_up(stop + v * t + (v * v - rho * rho * v * v) / (2 * a), 0.01);
  const std::string numbers = "v " + model::format_number(v, 3) + " m/s, t " + seconds(t) +
                              " (slowest source), a " + model::format_number(a, 3) + " m/s^2";
  refuse_unbounded_zone(rig, requirements, monitor, slow, numbers);
  monitor.zones.push_back(
      {"stop_zone",
       "stop",
       stop,
       "v t + v^2 / (2 a) = " + model::format_number(stop, 3) + " m ahead; " + numbers,
       {},
       {},
       {},
       kMinPoints,
       {}});
  monitor.zones.push_back({"slowdown_zone",
                           "slowdown",
                           slow,
                           "stop reach + v t + (v^2 - (" + model::format_number(rho, 3) +
                               " v)^2) / (2 a) = " + model::format_number(slow, 3) + " m ahead; " +
                               numbers,
                           {},
                           {},
                           {},
                           kMinPoints,
                           {}});
  const BodyOutline outline = body_outline(config);
  for (ProtectiveZone& zone : monitor.zones) {
    zone.points = swept_zone(outline, zone.reach);
    zone.visibility = zone_visibility(zone.points, outline, viewers, rig.body.area_top());
    for (std::size_t s = 0; s < viewers.size(); ++s) {
      if (zone.visibility.sees[s]) zone.sources.push_back(s);
    }
    if (requirements && requirements->smallest_obstacle && !zone.sources.empty()) {
      const double size = *requirements->smallest_obstacle;
      const int fewest = fewest_returns(zone, modes, origins, size);
      zone.min_points = std::clamp(fewest, 1, kMinPoints);
      if (fewest < kMinPoints) {
        zone.min_points_rule = "an R6 obstacle (" + model::format_number(size, 3) +
                               " m) at the zone's far corner gets " + std::to_string(fewest) +
                               " return(s) from the sparsest source that sees the zone";
      }
      if (fewest < 1) {
        monitor.notes.push_back("warning: " + zone.name +
                                ": an R6 obstacle can fall between "
                                "the rays of a source that sees the zone");
      }
    }
    if (!zone.visibility.unseen.empty()) {
      double unseen = 0.0;
      for (const BoundaryArc& arc : zone.visibility.unseen) unseen += arc.length;
      monitor.notes.push_back("warning: " + zone.name + ": " + model::format_number(unseen, 3) +
                              " m of its " +
                              model::format_number(zone.visibility.checked_boundary, 3) +
                              " m boundary is seen by no source");
    }
  }
  return monitor;
}

}  // namespace rigdesign::deploy
