#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "deploy/ros/nav2/nav2_keys.hpp"
#include "deploy/ros/nav2/parameter_file.hpp"
#include "deploy/ros/nav2/stvl_layer_reader.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/polygon_area.hpp"

namespace rigdesign::deploy {
namespace {

constexpr const char* kMetres = "metres, >= 0";

// nav2 writes `observation_sources: front_camera top_lidar`; a YAML list is taken too.
std::vector<std::string> source_names(io::MapReader& m) {
  const YAML::Node node = m.node("observation_sources");
  std::vector<std::string> names;
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) names.push_back(item.as<std::string>(""));
  } else if (node.IsScalar()) {
    std::istringstream words(node.Scalar());
    for (std::string word; words >> word;) names.push_back(word);
  } else if (node.IsDefined() && !node.IsNull()) {
    m.require(false, "observation_sources", "is not a list of names",
              "source names separated by spaces, e.g. `front_camera top_lidar`");
  }
  return names;
}

costmap::ObservationSource read_source(io::MapReader& m, costmap::ObservationSource source) {
  io::read_if_present(m, "marking", source.marking);
  io::read_if_present(m, "clearing", source.clearing);
  for (const nav2::SourceNumberKey& range : nav2::kSourceRangeKeys) {
    io::read_if_present(m, std::string(range.key), source.*range.field, kMetres);
  }
  for (const nav2::SourceNumberKey& range : nav2::kSourceRangeKeys) {
    m.require(source.*range.field >= 0.0, std::string(range.key), "is negative", kMetres);
  }
  for (const nav2::SourceNumberKey& height : nav2::kSourceHeightKeys) {
    io::read_if_present(m, std::string(height.key), source.*height.field,
                        "a world height in metres");
  }
  m.require(source.obstacle_min_range <= source.obstacle_max_range, "obstacle_min_range",
            "is above obstacle_max_range", "obstacle_min_range <= obstacle_max_range");
  const std::string persistence(nav2::kObservationPersistence);
  io::read_if_present(m, persistence, source.observation_persistence, "seconds, >= 0");
  m.require(source.observation_persistence >= 0.0, persistence, "is negative", "seconds, >= 0");
  m.require(source.min_obstacle_height <= source.max_obstacle_height, "min_obstacle_height",
            "is above max_obstacle_height", "min_obstacle_height <= max_obstacle_height");
  m.accept_keys(nav2::kIgnoredSourceKeys);
  m.reject_unknown_keys();
  return source;
}

// An obstacle or voxel layer: its sources, and for the voxel layer its column.
void read_obstacle_layer(io::MapReader& m, bool voxel, const costmap::ObservationSource& defaults,
                         CostmapParamsFile& file) {
  io::read_if_present(m, "track_unknown_space", file.costmap.obstacle.track_unknown_space);
  if (voxel) {
    costmap::VoxelLayerParams& v = file.costmap.voxel;
    io::read_if_present(m, "origin_z", v.z_min, "the column's bottom in metres");
    io::read_if_present(m, "z_resolution", v.z_resolution, "a voxel height in metres, > 0");
    int z_voxels = 0;
    io::read_if_present(m, "z_voxels", z_voxels, "a voxel count, > 0");
    if (m.has("z_voxels")) {
      m.require(z_voxels > 0, "z_voxels", "must be > 0", "a voxel count, > 0");
      v.z_max = v.z_min + z_voxels * v.z_resolution;
    }
    io::read_if_present(m, "unknown_threshold", v.unknown_threshold, "a voxel count, >= 0");
    int mark_threshold = 0;
    io::read_if_present(m, "mark_threshold", mark_threshold, "0");
    m.require(mark_threshold == 0, "mark_threshold", "is not 0",
              "0: one occupied voxel marks its column (the only rule rigdesign models)");
  }
  for (const std::string& name : source_names(m)) {
    file.has_sources = true;
    if (auto source = m.map(name, io::Need::required, "the source's parameters")) {
      file.sources.push_back({name, read_source(*source, defaults)});
      file.source_locations.push_back({m.location(name), source->location("obstacle_min_range"),
                                       source->location("obstacle_max_range"),
                                       source->location("min_obstacle_height"),
                                       source->location("max_obstacle_height")});
    }
  }
  m.accept_keys(nav2::kIgnoredLayerKeys);
  m.reject_unknown_keys();
}

void read_hit_layer(io::MapReader& m, costmap::HitLayerParams& hit) {
  io::read_if_present(m, "hit", hit.hit, "a count added per update, > 0");
  io::read_if_present(m, "hit_max", hit.hit_max, "the count's ceiling, >= hit");
  io::read_if_present(m, "d_threshold", hit.d_threshold,
                      "metres the robot must move to count as moving");
  io::read_if_present(m, "d_duration", hit.d_duration, "seconds over which the motion is judged");
  m.accept_keys({"plugin", "enabled"});
  m.reject_unknown_keys();
}

void read_inflation_layer(io::MapReader& m, costmap::InflationParams& inflation) {
  io::read_if_present(m, "inflation_radius", inflation.inflation_radius, kMetres);
  io::read_if_present(m, "cost_scaling_factor", inflation.cost_scaling_factor,
                      "a rate in 1/m, > 0");
  io::read_if_present(m, "inflate_unknown", inflation.inflate_unknown);
  m.accept_keys({"plugin", "enabled"});
  m.reject_unknown_keys();
}

// The node at a dotted key path below `node`, or an undefined node. Read through const
// nodes and reset(): yaml-cpp's non-const operator[] and operator= change the document.
YAML::Node node_at(const YAML::Node& node, const std::string& key_path) {
  YAML::Node current;
  current.reset(node);
  std::istringstream parts(key_path);
  for (std::string part; std::getline(parts, part, '.');) {
    if (!current.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node& parent = current;
    const YAML::Node child = parent[part];
    // A missing key gives an invalid node, which reset() would throw on (found by fuzzing).
    if (!child.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
    current.reset(child);
  }
  return current;
}

// Runs the costmap's own range checks and reports their findings at the file's keys.
void check_in_file_terms(const costmap::CostmapParams& params, const YAML::Node& block,
                         const std::string& block_path, const std::string& file) {
  try {
    costmap::check_costmap_params(params, io::location_of(block, file));
  } catch (const model::InputError& error) {
    std::vector<model::Diagnostic> located;
    for (model::Diagnostic d : error.diagnostics()) {
      for (const auto& [field, key] : nav2::kKeyOfField) {
        if (d.field != field) continue;
        const YAML::Node node = node_at(block, key);
        if (node.IsDefined()) d.where = io::location_of(node, file);
        d.field = (block_path.empty() ? "" : block_path + ".") + key;
      }
      located.push_back(std::move(d));
    }
    throw model::InputError(std::move(located));
  }
}

// nav2's footprint: a string "[[x, y], [x, y], ...]" (or the same as a YAML list). The
// costmap's round-robot geometry takes the circumscribed radius for the window and the
// collision check and the inscribed one for inflation, as nav2 derives both from a polygon.
void read_footprint(io::MapReader& m, CostmapParamsFile& file) {
  const std::string expected = "a polygon as nav2 writes it: \"[[x, y], [x, y], [x, y], ...]\"";
  const YAML::Node node = m.node("footprint");
  YAML::Node points = node;
  if (node.IsScalar()) {
    try {
      points = YAML::Load(node.Scalar());
    } catch (const YAML::Exception&) {
      points = YAML::Node();
    }
  }
  std::vector<model::Vec2> polygon;
  bool valid = points.IsSequence() && points.size() >= 3;
  for (std::size_t i = 0; valid && i < points.size(); ++i) {
    const YAML::Node point = points[i];
    valid = point.IsSequence() && point.size() == 2;
    double x = 0.0, y = 0.0;
    valid = valid && YAML::convert<double>::decode(point[0], x) &&
            YAML::convert<double>::decode(point[1], y) && std::isfinite(x) && std::isfinite(y);
    polygon.emplace_back(x, y);
  }
  if (!valid) {
    m.require(false, "footprint", "is not a polygon of at least three [x, y] points", expected);
    return;
  }
  const model::PolygonRadii radii = model::polygon_radii(polygon);
  const double outer = radii.circumscribed;
  m.require(outer > 0.0, "footprint", "has no extent", expected);
  file.footprint = polygon;
  file.costmap.robot_radius = outer;
  file.costmap.inflation.inscribed_radius = radii.inscribed;
}

// nav2 loads a layer's class through pluginlib: a class no installed package exports stops
// the costmap from configuring. rigdesign knows nav2's and STVL's; any other is a warning.
void warn_if_unknown_class(const YAML::Node& plugin, const std::string& layer,
                           const std::string& path, std::vector<model::Diagnostic>& warnings) {
  const std::string name = plugin.IsScalar() ? plugin.Scalar() : std::string();
  const auto& known = nav2::kKnownLayerClasses;
  if (std::find(known.begin(), known.end(), name) != known.end()) return;
  std::string classes;
  for (const std::string& known_class : known)
    classes += (classes.empty() ? "" : ", ") + known_class;
  warnings.push_back({io::location_of(plugin, path), layer + ".plugin",
                      "names '" + name +
                          "', a class neither nav2 (Humble, Jazzy) nor "
                          "spatio_temporal_voxel_layer exports: the costmap fails to configure "
                          "unless a package you build exports it",
                      "one of " + classes, model::Severity::warning});
}

bool listed(const std::vector<std::string>& plugins, std::string_view name) {
  return std::find(plugins.begin(), plugins.end(), name) != plugins.end();
}

// The map holding the parameters: nav2's node/namespace nesting, or the file itself.
YAML::Node parameter_block(const YAML::Node& root, std::string& path) {
  const auto map_at = [](const YAML::Node& node, const char* key) {
    const YAML::Node child = node.IsMap() ? node[key] : YAML::Node();
    return child.IsDefined() && child.IsMap() ? child : YAML::Node(YAML::NodeType::Undefined);
  };
  for (const char* costmap : {"local_costmap", "global_costmap"}) {
    const YAML::Node outer = map_at(root, costmap);
    if (!outer.IsDefined()) continue;
    const YAML::Node nested = map_at(outer, costmap);
    const YAML::Node inner = nested.IsDefined() ? nested : outer;
    path = std::string(costmap) + (nested.IsDefined() ? std::string(".") + costmap : "");
    const YAML::Node parameters = map_at(inner, "ros__parameters");
    if (parameters.IsDefined()) {
      path += ".ros__parameters";
      return parameters;
    }
    return inner;
  }
  return root;
}

}  // namespace

CostmapParamsFile load_costmap_params(const std::string& path,
                                      const costmap::CostmapParams& defaults,
                                      const costmap::ObservationSource& source_defaults,
                                      double global_frame_height) {
  model::Diagnostics diagnostics;
  nav2::ParameterMap parameters = nav2::read_parameter_map(
      path, diagnostics, parameter_block,
      "nav2 costmap parameters: local_costmap: local_costmap: ros__parameters: {...}");
  io::MapReader& m = parameters.reader;
  const YAML::Node& block = parameters.block;
  const std::string& block_path = parameters.block_path;
  CostmapParamsFile file{defaults, {}, {}, false, {}, {}, {}};
  file.window_where = m.location(m.has("width") ? "width" : m.has("height") ? "height" : "");
  costmap::CostmapParams& p = file.costmap;
  io::read_if_present(m, "resolution", p.resolution, "a cell side in metres, > 0");
  io::read_if_present(m, "width", p.size_x, "the window's side along x in metres, > 0");
  io::read_if_present(m, "height", p.size_y, "the window's side along y in metres, > 0");
  if (m.has("robot_radius")) {
    io::read_if_present(m, "robot_radius", p.robot_radius, kMetres);
    p.inflation.inscribed_radius = p.robot_radius;  // a round robot: nav2 does the same
  }
  if (m.has("footprint")) read_footprint(m, file);
  if (m.has("plugins")) {
    std::vector<std::string> plugins;
    const YAML::Node list = m.node("plugins");
    if (list.IsSequence()) {
      for (const YAML::Node& item : list) plugins.push_back(item.as<std::string>(""));
    } else {
      m.require(false, "plugins", "is not a list", "e.g. [\"voxel_layer\", \"inflation_layer\"]");
    }
    const bool obstacle = listed(plugins, nav2::kObstacleLayer);
    const bool voxel = listed(plugins, nav2::kVoxelLayer);
    m.require(!(obstacle && voxel), "plugins", "lists both obstacle_layer and voxel_layer",
              "one of obstacle_layer (2D) and voxel_layer (3D)");
    if (obstacle) p.layer = costmap::ObstacleLayerKind::obstacle;
    if (voxel) p.layer = costmap::ObstacleLayerKind::voxel;
    p.use_hit_layer = listed(plugins, nav2::kHitLayer);
    // nav2 loads each listed layer by its `plugin` class: a layer without one fails to start.
    for (const std::string& name : plugins) {
      const YAML::Node layer = m.node(name);
      if (!layer.IsDefined() || layer.IsNull()) {
        m.require(false, "plugins", "lists '" + name + "', which is not given",
                  "a map `" + name + ":` with its plugin and parameters");
        continue;
      }
      const YAML::Node& const_layer = layer;
      const bool has_plugin = const_layer.IsMap() && const_layer["plugin"].IsDefined();
      m.require(has_plugin, name, "has no plugin",
                "plugin: the layer's class, e.g. \"nav2_costmap_2d::VoxelLayer\"");
      if (has_plugin) warn_if_unknown_class(const_layer["plugin"], name, path, file.warnings);
    }
  }
  for (const auto& [key, voxel] :
       {std::pair{nav2::kObstacleLayer, false}, {nav2::kVoxelLayer, true}}) {
    if (auto layer = m.map(std::string(key), io::Need::optional)) {
      read_obstacle_layer(*layer, voxel, source_defaults, file);
    }
  }
  // spatio_temporal_voxel_layer (export --layer stvl): 3D sources, simulated as a voxel layer's.
  if (auto stvl = m.map(std::string(nav2::kStvlLayer), io::Need::optional)) {
    read_stvl_layer(*stvl, source_defaults, file);
    p.layer = costmap::ObstacleLayerKind::voxel;
  }
  if (auto hit = m.map(std::string(nav2::kHitLayer), io::Need::optional))
    read_hit_layer(*hit, p.hit);
  if (auto inflation = m.map(std::string(nav2::kInflationLayer), io::Need::optional)) {
    read_inflation_layer(*inflation, p.inflation);
  }
  m.accept_keys(nav2::kIgnoredCostmapKeys);
  m.reject_unknown_keys();
  diagnostics.throw_if_errors();
  // The file's heights are in its global frame; rigdesign's above the floor.
  if (global_frame_height != 0.0) {
    for (costmap::NamedObservationSource& named : file.sources) {
      named.source.min_obstacle_height += global_frame_height;
      named.source.max_obstacle_height += global_frame_height;
    }
    if (m.has(std::string(nav2::kVoxelLayer))) {
      p.voxel.z_min += global_frame_height;
      p.voxel.z_max += global_frame_height;
    }
  }
  // The ranges and counts are checked in one place, the costmap's own check.
  check_in_file_terms(p, block, block_path, path);
  return file;
}

}  // namespace rigdesign::deploy
