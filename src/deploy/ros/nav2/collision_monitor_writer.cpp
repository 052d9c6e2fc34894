#include "rigdesign/deploy/ros/nav2/collision_monitor_writer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rigdesign/io/emit/yaml_emit.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::deploy {
namespace {

// A coordinate to 0.1 mm (far below any zone's sizing), always with a decimal point: Humble
// declares points a double array and refuses a whole number in it.
std::string coordinate(double metres) {
  return io::yaml_float(std::round(metres * 1e4) / 1e4);
}

// The zone's corners on the floor, in the base frame (the base link may stand above the floor
// or off the robot frame's axis).
std::vector<model::Vec2> in_base_frame(const deploy::CollisionMonitor& monitor,
                                       const std::vector<model::Vec2>& points) {
  const model::Pose3 T_base_robot = monitor.T_robot_base.inverse();
  std::vector<model::Vec2> moved;
  for (const model::Vec2& p : points) {
    moved.push_back((T_base_robot * model::Vec3(p.x(), p.y(), 0.0)).head<2>());
  }
  return moved;
}

// Jazzy reads a string of [x, y] pairs (nav2_util::parseVVF), Humble a flat list of numbers.
std::string points_value(const std::vector<model::Vec2>& points, bool jazzy) {
  std::string text = jazzy ? "\"[" : "[";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i) text += ", ";
    const std::string x = coordinate(points[i].x());
    const std::string y = coordinate(points[i].y());
    text += jazzy ? "[" + x + ", " + y + "]" : x + ", " + y;
  }
  return text + (jazzy ? "]\"" : "]");
}

std::string name_list(const std::vector<std::string>& names) {
  std::string text = "[";
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i ? ", " : "") + io::yaml_quoted(names[i]);
  return text + "]";
}

}  // namespace

std::string collision_monitor_text(const deploy::CollisionMonitor& monitor,
                                   const deploy::CostmapConfig& config, const std::string& header) {
  const bool jazzy = monitor.distro != "humble";
  std::ostringstream out;
  out << io::yaml_comment(header);
  out << io::yaml_comment("nav2 collision_monitor for ROS 2 " + monitor.distro +
                          " (export --ros-distro). Zones in " + monitor.base_frame + "; speed " +
                          model::format_number(monitor.speed, 3) + " m/s, deceleration " +
                          model::format_number(monitor.deceleration, 3) + " m/s^2 (" +
                          monitor.deceleration_from + ").");
  for (const deploy::CollisionSource& source : monitor.sources) {
    out << io::yaml_comment("latency of " + config.sources[source.source].mount_id + ": " +
                            model::format_number(source.latency, 3) +
                            " s = " + source.latency_rule);
  }
  for (const std::string& note : monitor.notes) out << io::yaml_comment(note);
  // Only sources that see a zone are subscribed: a stale source stops the robot (Jazzy).
  std::vector<bool> feeds(monitor.sources.size(), false);
  for (const deploy::ProtectiveZone& zone : monitor.zones)
    for (const std::size_t s : zone.sources) feeds[s] = true;
  // No source sees any zone: nav2 still needs a source list (an empty one has no type), so
  // every source is listed; the warnings above say the zones are blind.
  if (std::find(feeds.begin(), feeds.end(), true) == feeds.end()) feeds.assign(feeds.size(), true);
  std::vector<std::string> source_names;
  for (std::size_t s = 0; s < monitor.sources.size(); ++s) {
    if (feeds[s]) source_names.push_back(config.sources[monitor.sources[s].source].mount_id);
  }
  const std::string in = "    ";
  out << "collision_monitor:\n  ros__parameters:\n";
  io::write_key(out, in, "base_frame_id", io::yaml_scalar(monitor.base_frame));
  io::write_key(out, in, "odom_frame_id", "odom");
  io::write_key(out, in, "cmd_vel_in_topic", io::yaml_quoted("cmd_vel_smoothed"),
                "the velocity smoother's output, as nav2_bringup chains them");
  io::write_key(out, in, "cmd_vel_out_topic", io::yaml_quoted("cmd_vel"));
  if (jazzy) io::write_key(out, in, "state_topic", io::yaml_quoted("collision_monitor_state"));
  std::vector<std::string> zone_names;
  for (const deploy::ProtectiveZone& zone : monitor.zones) zone_names.push_back(zone.name);
  io::write_key(out, in, "polygons", name_list(zone_names));
  const std::string z = in + "  ";
  for (const deploy::ProtectiveZone& zone : monitor.zones) {
    out << in << io::yaml_scalar(zone.name) << ":\n";
    out << io::yaml_comment(zone.sizing, z);
    for (const deploy::BoundaryArc& arc : zone.visibility.unseen) {
      out << io::yaml_comment("unseen by every source: " + model::format_number(arc.length, 3) +
                                  " m of boundary from (" + coordinate(arc.from.x()) + ", " +
                                  coordinate(arc.from.y()) + ") to (" + coordinate(arc.to.x()) +
                                  ", " + coordinate(arc.to.y()) + ")",
                              z);
    }
    io::write_key(out, z, "type", io::yaml_quoted("polygon"));
    io::write_key(out, z, "points", points_value(in_base_frame(monitor, zone.points), jazzy));
    io::write_key(out, z, "action_type", io::yaml_quoted(zone.action));
    // Humble acts above max_points, Jazzy at min_points: the same count either way.
    if (jazzy) {
      io::write_key(out, z, "min_points", std::to_string(zone.min_points), zone.min_points_rule);
    } else {
      io::write_key(out, z, "max_points", std::to_string(zone.min_points - 1),
                    zone.min_points_rule);
    }
    if (zone.action == "slowdown")
      io::write_key(out, z, "slowdown_ratio", io::yaml_float(monitor.slowdown_ratio));
    io::write_key(out, z, "visualize", io::yaml_bool(true));
    io::write_key(out, z, "polygon_pub_topic", io::yaml_quoted(zone.name));
    io::write_key(out, z, "enabled", io::yaml_bool(true));
    if (jazzy && !zone.sources.empty()) {
      std::vector<std::string> names;
      for (const std::size_t s : zone.sources)
        names.push_back(config.sources[monitor.sources[s].source].mount_id);
      io::write_key(out, z, "sources_names", name_list(names),
                    "the sources whose FOV reaches the zone (nav2 >= 1.3.3)");
    }
  }
  io::write_key(out, in, "observation_sources", name_list(source_names));
  for (std::size_t s = 0; s < monitor.sources.size(); ++s) {
    if (!feeds[s]) continue;
    const deploy::CollisionSource& source = monitor.sources[s];
    const deploy::SourceConfig& costmap_source = config.sources[source.source];
    out << in << io::yaml_scalar(costmap_source.mount_id) << ":\n";
    io::write_key(out, z, "type",
                  io::yaml_quoted(costmap_source.laser_scan ? "scan" : "pointcloud"));
    io::write_key(out, z, "topic", io::yaml_scalar(costmap_source.topic), "the costmap's topic");
    if (!costmap_source.laser_scan) {
      const double base_z = monitor.T_robot_base.translation().z();
      io::write_key(out, z, "min_height", io::yaml_float(source.min_z - base_z),
                    "the costmap's min_obstacle_height, in " + monitor.base_frame);
      io::write_key(out, z, "max_height", io::yaml_float(source.max_z - base_z),
                    "the costmap's max_obstacle_height, in " + monitor.base_frame);
    }
    io::write_key(out, z, "enabled", io::yaml_bool(true));
  }
  return out.str();
}

}  // namespace rigdesign::deploy
