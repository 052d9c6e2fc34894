#include "deploy/ros/nav2/stvl_layer_reader.hpp"

#include <limits>
#include <sstream>

#include "rigdesign/io/config/field_checks.hpp"

namespace rigdesign::deploy {
namespace {

constexpr const char* kStvlMetres = "metres, >= 0";
// A voxel STVL never decays (decay_model other than 0 linear and 1 exponential) is kept this
// long: longer than any check asks for.
constexpr double kForever = 1e9;  // [s]

const std::vector<std::string> kIgnoredStvlLayerKeys = {"plugin",
                                                        "enabled",
                                                        "voxel_size",
                                                        "track_unknown_space",
                                                        "mark_threshold",
                                                        "update_footprint_enabled",
                                                        "combination_method",
                                                        "publish_voxel_map",
                                                        "mapping_mode",
                                                        "map_save_duration",
                                                        "transform_tolerance",
                                                        "voxel_distance_decay"};
const std::vector<std::string> kIgnoredStvlSourceKeys = {"topic",
                                                         "data_type",
                                                         "sensor_frame",
                                                         "expected_update_rate",
                                                         "inf_is_valid",
                                                         "voxel_min_points",
                                                         "clear_after_reading",
                                                         "enabled",
                                                         "model_type",
                                                         "horizontal_fov_angle",
                                                         "vertical_fov_angle",
                                                         "vertical_fov_padding",
                                                         "vertical_fov_offset",
                                                         "decay_acceleration",
                                                         "transport_type"};

costmap::ObservationSource read_stvl_source(io::MapReader& m, costmap::ObservationSource source,
                                            double keep) {
  io::read_if_present(m, "marking", source.marking);
  io::read_if_present(m, "clearing", source.clearing);
  source.obstacle_min_range = 0.0;  // STVL marks from the sensor on
  io::read_if_present(m, "obstacle_range", source.obstacle_max_range, kStvlMetres);
  io::read_if_present(m, "min_z", source.raytrace_min_range, kStvlMetres);
  io::read_if_present(m, "max_z", source.raytrace_max_range, kStvlMetres);
  for (const char* key : {"obstacle_range", "min_z", "max_z"}) {
    const std::optional<double> value = m.number(key, io::Need::optional, kStvlMetres);
    m.require(!value || *value >= 0.0, key, "is negative", kStvlMetres);
  }
  m.require(source.raytrace_min_range <= source.raytrace_max_range, "min_z", "is above max_z",
            "min_z <= max_z");
  io::read_if_present(m, "min_obstacle_height", source.min_obstacle_height,
                      "a world height in metres");
  io::read_if_present(m, "max_obstacle_height", source.max_obstacle_height,
                      "a world height in metres");
  const std::string filter = m.text("filter", io::Need::optional).value_or("passthrough");
  if (filter != "passthrough" && filter != "voxel") {
    // STVL applies the height band only inside those two filters: every height marks.
    source.min_obstacle_height = -std::numeric_limits<double>::max();
    source.max_obstacle_height = std::numeric_limits<double>::max();
  }
  m.require(source.min_obstacle_height <= source.max_obstacle_height, "min_obstacle_height",
            "is above max_obstacle_height", "min_obstacle_height <= max_obstacle_height");
  io::read_if_present(m, "observation_persistence", source.observation_persistence,
                      "seconds, >= 0");
  m.require(source.observation_persistence >= 0.0, "observation_persistence", "is negative",
            "seconds, >= 0");
  // The layer's decay keeps a marked voxel however the source's own buffer is kept.
  source.observation_persistence = std::max(source.observation_persistence, keep);
  m.accept_keys(kIgnoredStvlSourceKeys);
  m.reject_unknown_keys();
  return source;
}

}  // namespace

void read_stvl_layer(io::MapReader& m, const costmap::ObservationSource& defaults,
                     CostmapParamsFile& file) {
  int decay_model = 0;
  double voxel_decay = -1.0;  // STVL's default
  io::read_if_present(m, "decay_model", decay_model, "0 (linear), 1 (exponential) or other (none)");
  io::read_if_present(m, "voxel_decay", voxel_decay, "seconds");
  const double keep = decay_model == 0 || decay_model == 1 ? std::max(0.0, voxel_decay) : kForever;
  std::vector<std::string> names;
  if (const std::optional<std::string> list =
          m.text("observation_sources", io::Need::optional, "source names separated by spaces")) {
    std::istringstream words(*list);
    for (std::string word; words >> word;) names.push_back(word);
  }
  for (const std::string& name : names) {
    file.has_sources = true;
    if (auto source = m.map(name, io::Need::required, "the source's parameters")) {
      file.sources.push_back({name, read_stvl_source(*source, defaults, keep)});
      file.source_locations.push_back(
          {m.location(name), source->location("obstacle_range"), source->location("obstacle_range"),
           source->location("min_obstacle_height"), source->location("max_obstacle_height")});
    }
  }
  m.accept_keys(kIgnoredStvlLayerKeys);
  m.reject_unknown_keys();
}

}  // namespace rigdesign::deploy
