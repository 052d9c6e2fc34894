#include "rigdesign/deploy/ros/nav2/collision_monitor_reader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "deploy/ros/nav2/collision_monitor_keys.hpp"
#include "deploy/ros/nav2/parameter_file.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/polygon_checks.hpp"

namespace rigdesign::deploy {
namespace {

constexpr const char* kPointsForm =
    "a polygon of at least 4 corners as nav2 reads it: Jazzy \"[[x, y], [x, y], ...]\", "
    "Humble [x1, y1, x2, y2, ...]";
// A circle zone is checked as this many points on it.
constexpr int kCircleCorners = 64;

// nav2 declares these as string arrays: a YAML list of names.
std::vector<std::string> name_list(io::MapReader& m, const std::string& key, io::Need need,
                                   const std::string& example) {
  const YAML::Node node = m.node(key);
  std::vector<std::string> names;
  const bool present = node.IsDefined() && !node.IsNull();
  if (!present) {
    m.require(need == io::Need::optional, key, "is missing", "a list of names, e.g. " + example);
    return names;
  }
  bool valid = node.IsSequence();
  for (std::size_t i = 0; valid && i < node.size(); ++i) {
    valid = node[i].IsScalar() && !node[i].Scalar().empty();
    if (valid) names.push_back(node[i].Scalar());
  }
  m.require(valid, key, "is not a list of names", "a list of names, e.g. " + example);
  return names;
}

// A pair list parsed from Jazzy's string, or Humble's flat numbers paired up; nothing when
// the value is neither.
std::optional<std::vector<model::Vec2>> polygon_points(const YAML::Node& node) {
  std::vector<double> numbers;
  if (node.IsScalar()) {
    YAML::Node pairs;
    try {
      pairs = YAML::Load(node.Scalar());
    } catch (const YAML::Exception&) {
      return std::nullopt;
    }
    if (!pairs.IsSequence()) return std::nullopt;
    for (const YAML::Node& pair : pairs) {
      if (!pair.IsSequence() || pair.size() != 2) return std::nullopt;
      for (const YAML::Node& value : pair) {
        double v = 0.0;
        if (!value.IsScalar() || !YAML::convert<double>::decode(value, v)) return std::nullopt;
        numbers.push_back(v);
      }
    }
  } else if (node.IsSequence()) {
    if (node.size() % 2 != 0) return std::nullopt;
    for (const YAML::Node& value : node) {
      double v = 0.0;
      if (!value.IsScalar() || !YAML::convert<double>::decode(value, v)) return std::nullopt;
      numbers.push_back(v);
    }
  } else {
    return std::nullopt;
  }
  std::vector<model::Vec2> points;
  for (std::size_t i = 0; i + 1 < numbers.size(); i += 2) {
    if (!std::isfinite(numbers[i]) || !std::isfinite(numbers[i + 1])) return std::nullopt;
    points.emplace_back(numbers[i], numbers[i + 1]);
  }
  return points;
}

// A protective zone reaching farther than any mobile robot brakes: typed in millimetres?
void warn_if_far(io::MapReader& m, const deploy::DeployedZone& zone) {
  constexpr double kFarZone = 50.0;  // [m] 1 m/s braking at 0.01 m/s^2 stops within 50 m
  double farthest = 0.0;
  for (const model::Vec2& p : zone.points) farthest = std::max(farthest, p.norm());
  if (farthest <= kFarZone) return;
  m.diagnostics().warning(zone.points_where, m.field(zone.type == "circle" ? "radius" : "points"),
                          "reaches " + model::format_number(farthest, 4) +
                              " m from the robot: a stop zone that large is probably typed in "
                              "millimetres",
                          "metres (nav2 reads every zone in metres)");
}

deploy::DeployedZone read_zone(io::MapReader& m, const std::string& name,
                               const std::vector<std::string>& sources) {
  deploy::DeployedZone zone;
  zone.name = name;
  zone.where = m.location();
  const std::vector<std::string> types = {"polygon", "circle", "velocity_polygon"};
  if (auto type = m.choice("type", io::Need::required, types)) zone.type = types[*type];
  const std::vector<std::string> actions = {"stop", "slowdown", "limit", "approach", "none"};
  if (auto action = m.choice("action_type", io::Need::required, actions)) {
    zone.action = actions[*action];
  }
  io::read_if_present(m, "enabled", zone.enabled);
  if (zone.type == "polygon" && m.has("points")) {
    zone.points_where = m.location("points");
    const auto points = polygon_points(m.node("points"));
    m.require(points && points->size() >= 4, "points", "is not a polygon nav2 accepts",
              kPointsForm);
    if (points && points->size() >= 4) {
      const std::optional<std::string> problem = model::polygon_problem(*points);
      m.require(!problem, "points", problem.value_or(""),
                "a simple polygon around the robot, in metres");
      if (!problem) zone.points = *points;
    }
  } else if (zone.type == "circle" && m.has("radius")) {
    zone.points_where = m.location("radius");
    const double radius =
        io::positive_length(m, "radius", io::Need::required, "the circle's radius in m");
    for (int k = 0; radius > 0.0 && k < kCircleCorners; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / kCircleCorners;
      zone.points.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
  }
  warn_if_far(m, zone);
  if (zone.type == "velocity_polygon") {
    // Its sub-polygons are maps named in velocity_polygons: read past, not checked.
    for (const std::string& sub :
         name_list(m, "velocity_polygons", io::Need::optional, "[\"fwd\"]"))
      m.accept_keys({sub});
  }
  if (m.has("sources_names")) {
    zone.sources_names = name_list(m, "sources_names", io::Need::required, "[\"front_lidar\"]");
    for (const std::string& source : *zone.sources_names) {
      // nav2 refuses to configure with a name that is no observation source.
      m.require(std::find(sources.begin(), sources.end(), source) != sources.end(), "sources_names",
                "names '" + source + "', which is no observation source",
                "names from observation_sources: " + model::join(sources));
    }
  }
  m.accept_keys(nav2::kMonitorPolygonKeys.ignored);
  m.reject_unknown_keys();
  return zone;
}

// The mount a source reads: the one it is named after, else the one whose topic it reads.
std::string mount_of(const model::Rig& rig, const std::vector<MountTopic>& mount_topics,
                     const std::string& name, const std::string& topic) {
  if (rig.find_mount(name)) return name;
  for (const auto& [mount_topic, mount] : mount_topics) {
    if (mount_topic == topic) return mount;
  }
  return "";
}

deploy::DeployedMonitorSource read_source(io::MapReader& m, const std::string& name,
                                          const model::Rig& rig,
                                          const std::vector<MountTopic>& mount_topics) {
  deploy::DeployedMonitorSource source;
  source.name = name;
  source.where = m.location();
  const std::vector<std::string> types = {"scan", "pointcloud", "range", "polygon"};
  source.type = "scan";  // nav2's default
  if (auto type = m.choice("type", io::Need::optional, types)) source.type = types[*type];
  const std::string topic = m.text("topic", io::Need::optional).value_or("scan");  // nav2's default
  io::read_if_present(m, "enabled", source.enabled);
  io::read_if_present(m, "min_height", source.min_height, "a height in m in the base frame");
  io::read_if_present(m, "max_height", source.max_height, "a height in m in the base frame");
  m.require(source.min_height <= source.max_height, "min_height", "is above max_height",
            "min_height <= max_height");
  source.min_range = io::non_negative(m, "min_range", io::Need::optional, "metres, >= 0");
  if (source.type == "scan" || source.type == "pointcloud") {
    source.mount_id = mount_of(rig, mount_topics, name, topic);
    std::string topics;
    for (const auto& [mount_topic, mount] : mount_topics)
      topics += (topics.empty() ? "" : ", ") + mount + " " + mount_topic;
    m.require(!source.mount_id.empty(), "topic",
              "'" + topic + "' is no mount's topic and '" + name + "' no mount of " + rig.file,
              "a source named after a mount (" + model::join(rig.mount_ids()) +
                  ") or reading its topic (" + topics + ")");
  }
  m.accept_keys(nav2::kMonitorSourceKeys.ignored);
  m.reject_unknown_keys();
  return source;
}

// The map holding the parameters: collision_monitor: ros__parameters:, or the file itself.
YAML::Node monitor_block(const YAML::Node& root, std::string& path) {
  YAML::Node current;
  current.reset(root);
  for (const char* key : {"collision_monitor", "ros__parameters"}) {
    if (!current.IsMap()) break;
    const YAML::Node& parent = current;
    const YAML::Node child = parent[key];
    if (!child.IsDefined() || !child.IsMap()) break;
    path += (path.empty() ? "" : ".") + std::string(key);
    current.reset(child);
  }
  return current;
}

}  // namespace

deploy::DeployedCollisionMonitor load_collision_monitor(
    const std::string& path, const model::Rig& rig, const std::vector<MountTopic>& mount_topics) {
  model::Diagnostics diagnostics;
  nav2::ParameterMap parameters = nav2::read_parameter_map(
      path, diagnostics, monitor_block,
      "nav2 collision monitor parameters: collision_monitor: ros__parameters: {...}");
  io::MapReader& m = parameters.reader;
  deploy::DeployedCollisionMonitor monitor;
  monitor.file = path;
  if (m.has("base_frame_id")) {
    monitor.base_frame =
        io::frame_id(m, "base_frame_id", io::Need::required, "the robot's base frame");
  }
  const std::vector<std::string> polygons =
      name_list(m, "polygons", io::Need::required, "[\"stop_zone\"]");
  const std::vector<std::string> sources =
      name_list(m, "observation_sources", io::Need::required, "[\"front_lidar\"]");
  for (const std::string& name : polygons) {
    if (auto zone = m.map(name, io::Need::required, "the polygon's parameters")) {
      monitor.zones.push_back(read_zone(*zone, name, sources));
      if (monitor.zones.back().type == "velocity_polygon") {
        monitor.warnings.push_back({zone->location(), zone->path(),
                                    "is a velocity_polygon: its sub-polygons are not checked",
                                    "a polygon or circle zone", model::Severity::warning});
      }
    }
  }
  for (const std::string& name : sources) {
    if (auto source = m.map(name, io::Need::required, "the source's parameters")) {
      monitor.sources.push_back(read_source(*source, name, rig, mount_topics));
      const deploy::DeployedMonitorSource& read = monitor.sources.back();
      if (read.mount_id.empty()) {
        monitor.warnings.push_back({read.where, source->path(),
                                    "is a " + read.type + " source: rigdesign does not model it",
                                    "a scan or pointcloud source", model::Severity::warning});
      }
    }
  }
  m.accept_keys(nav2::kMonitorNodeKeys.ignored);
  m.reject_unknown_keys();
  diagnostics.throw_if_errors();
  // The reader's own warnings (a zone probably in millimetres) go with the file's others.
  monitor.warnings.insert(monitor.warnings.begin(), diagnostics.items().begin(),
                          diagnostics.items().end());
  return monitor;
}

}  // namespace rigdesign::deploy
