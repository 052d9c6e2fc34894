#include "rigdesign/deploy/collision_monitor_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/deploy/collision_monitor.hpp"
#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {
namespace {

std::string point_text(const model::Vec2& p) {
  return "(" + model::format_number(p.x(), 3) + ", " + model::format_number(p.y(), 3) + ")";
}

std::string azimuth_text(const model::Vec2& p) {
  return model::format_number(model::rad_to_deg(std::atan2(p.y(), p.x())), 3);
}

bool has_area(const DeployedZone& zone) {
  return zone.enabled && zone.points.size() >= 3 && zone.action != "approach" &&
         zone.action != "none" && zone.type != "velocity_polygon";
}

// The zone's sources: its sources_names, else every source; enabled ones on a mount only.
std::vector<const DeployedMonitorSource*> zone_sources(const DeployedCollisionMonitor& monitor,
                                                       const DeployedZone& zone) {
  std::vector<const DeployedMonitorSource*> sources;
  for (const DeployedMonitorSource& source : monitor.sources) {
    const bool named =
        !zone.sources_names || std::find(zone.sources_names->begin(), zone.sources_names->end(),
                                         source.name) != zone.sources_names->end();
    if (named && source.enabled && !source.mount_id.empty()) sources.push_back(&source);
  }
  return sources;
}

}  // namespace

std::vector<metrics::RequirementResult> check_collision_monitor(
    const model::Rig& rig, const model::SensorLibrary& library,
    const DeployedCollisionMonitor& monitor) {
  const std::optional<model::Pose3> T_robot_base = robot_frame_pose(rig, monitor.base_frame);
  if (!T_robot_base) {
    throw model::InputError(
        model::Diagnostic{{monitor.file},
                          "base_frame_id",
                          "'" + monitor.base_frame + "' is no frame of " + rig.file,
                          "base_footprint or a link of the robot's description"});
  }
  const double base_z = T_robot_base->translation().z();
  // The outline nav2's footprint takes (export's rule), the body as every check occludes with.
  const BodyOutline outline = body_outline(costmap_config(rig, library, nullptr, {}));
  const geometry::BodyOccluder occluder(rig.body);
  std::vector<metrics::RequirementResult> results;
  for (const DeployedZone& zone : monitor.zones) {
    if (!has_area(zone)) continue;
    const std::vector<const DeployedMonitorSource*> sources = zone_sources(monitor, zone);
    std::vector<geometry::MountedFov> fovs;
    fovs.reserve(sources.size());
    std::vector<ZoneViewer> viewers;
    std::vector<std::string> names;
    for (const DeployedMonitorSource* source : sources) {
      const model::Mount& mount = *rig.find_mount(source->mount_id);
      model::MountLimits limits;
      if (source->min_range > 0.0) limits.min_range = source->min_range;
      fovs.emplace_back(library.resolved_mode(mount.sensor_id, mount.mode_id), mount.T_robot_sensor,
                        occluder, mount.housing_link, limits,
                        geometry::housings_around(rig, library, mount.id));
      names.push_back(source->name);
    }
    for (std::size_t s = 0; s < sources.size(); ++s) {
      const bool scan = sources[s]->type == "scan";
      viewers.push_back(
          {&fovs[s], scan ? 0.0 : sources[s]->min_height + base_z,
           scan ? std::numeric_limits<double>::infinity() : sources[s]->max_height + base_z});
    }
    std::vector<model::Vec2> points;
    for (const model::Vec2& p : zone.points) {
      points.push_back((*T_robot_base * model::Vec3(p.x(), p.y(), 0.0)).head<2>());
    }
    const ZoneVisibility visibility =
        zone_visibility(points, outline, viewers, rig.body.area_top());
    metrics::RequirementResult r;
    r.id = "D4";
    r.title = "collision monitor zone " + zone.name + " seen on its whole edge";
    r.metric = "unseen edge";
    r.field = zone.name + ".points";
    r.unit = "m";
    r.required = 0.0;
    r.bound = metrics::Bound::at_most;
    r.where = zone.points_where;
    double unseen = 0.0;
    std::string arcs;
    for (const BoundaryArc& arc : visibility.unseen) {
      unseen += arc.length;
      arcs += (arcs.empty() ? "" : "; ") + model::format_number(arc.length, 3) + " m from " +
              point_text(arc.from) + " to " + point_text(arc.to) + " (azimuth " +
              azimuth_text(arc.from) + " to " + azimuth_text(arc.to) + " deg)";
    }
    r.actual = unseen;
    for (std::size_t s = 0; s < sources.size(); ++s) {
      if (visibility.sees[s]) r.limiting_mounts.push_back(sources[s]->mount_id);
    }
    const std::string by = "its sources " + model::join(names);
    if (visibility.unseen.empty()) {
      r.explanation = zone.name + " (" + zone.action + "): all " +
                      model::format_number(visibility.checked_boundary, 3) +
                      " m of its edge outside the robot is seen by " + by;
    } else {
      r.verdict = metrics::Verdict::fail;
      const std::string none =
          names.empty() ? "no source (none of its sources is an enabled scan or pointcloud on a "
                          "mount)"
                        : "none of " + by;
      r.explanation = zone.name + " (" + zone.action + "): " + model::format_number(unseen, 3) +
                      " m of its " + model::format_number(visibility.checked_boundary, 3) +
                      " m edge outside the robot is seen by " + none + " (robot frame, floor to " +
                      model::format_number(rig.body.area_top(), 3) + " m): " + arcs;
    }
    results.push_back(std::move(r));
  }
  return results;
}

}  // namespace rigdesign::deploy
