#pragma once
// nav2's costmap parameter names, in one table that the reader and the writer of
// nav2_costmap.yaml share: the layer names nav2_bringup lists in `plugins`, the classes nav2
// loads for them, the observation-source keys rigdesign models, the keys it reads past, and
// where check_costmap_params' struct fields stand in the file. The names are nav2's own
// (nav2_costmap_2d's declareParameter calls; docs/costmap.md, "Parameter files").
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rigdesign/costmap/observation.hpp"

namespace rigdesign::deploy::nav2 {

// Layer names as nav2_bringup's parameter files list them in `plugins`.
inline constexpr std::string_view kObstacleLayer = "obstacle_layer";
inline constexpr std::string_view kVoxelLayer = "voxel_layer";
inline constexpr std::string_view kHitLayer = "hit_layer";
inline constexpr std::string_view kInflationLayer = "inflation_layer";
inline constexpr std::string_view kStaticLayer = "static_layer";
inline constexpr std::string_view kStvlLayer = "stvl_layer";

// The `plugin` class nav2 loads for each layer.
inline constexpr std::string_view kObstacleLayerClass = "nav2_costmap_2d::ObstacleLayer";
inline constexpr std::string_view kVoxelLayerClass = "nav2_costmap_2d::VoxelLayer";
inline constexpr std::string_view kInflationLayerClass = "nav2_costmap_2d::InflationLayer";
inline constexpr std::string_view kStaticLayerClass = "nav2_costmap_2d::StaticLayer";
inline constexpr std::string_view kStvlLayerClass =
    "spatio_temporal_voxel_layer/SpatioTemporalVoxelLayer";

/// A source's keep time [s] (costmap::ObservationSource::observation_persistence).
inline constexpr std::string_view kObservationPersistence = "observation_persistence";

/// Layer classes a costmap may load without a warning from `check --nav2`: nav2_costmap_2d's
/// (costmap_plugins.xml, Humble and Jazzy) and spatio_temporal_voxel_layer's. The table with
/// file and commit is data/ros_parameters/nav2_costmap_2d.yaml.
extern const std::vector<std::string> kKnownLayerClasses;

/// An observation source's number that rigdesign models: its key and its field.
struct SourceNumberKey {
  std::string_view key;
  double costmap::ObservationSource::*field;
};
/// The marking and clearing ranges [m], in the order nav2's documentation lists them.
inline constexpr std::array<SourceNumberKey, 4> kSourceRangeKeys = {{
    {"obstacle_min_range", &costmap::ObservationSource::obstacle_min_range},
    {"obstacle_max_range", &costmap::ObservationSource::obstacle_max_range},
    {"raytrace_min_range", &costmap::ObservationSource::raytrace_min_range},
    {"raytrace_max_range", &costmap::ObservationSource::raytrace_max_range},
}};
/// The height band [m] of points that mark.
inline constexpr std::array<SourceNumberKey, 2> kSourceHeightKeys = {{
    {"min_obstacle_height", &costmap::ObservationSource::min_obstacle_height},
    {"max_obstacle_height", &costmap::ObservationSource::max_obstacle_height},
}};

/// nav2 parameters rigdesign reads past: they name topics, frames and rates of a running
/// stack, which a simulation on recorded geometry does not need.
extern const std::vector<std::string> kIgnoredCostmapKeys;
extern const std::vector<std::string> kIgnoredLayerKeys;
extern const std::vector<std::string> kIgnoredSourceKeys;

/// check_costmap_params names struct members; the file names nav2 keys. Field path -> key path.
extern const std::vector<std::pair<std::string, std::string>> kKeyOfField;

}  // namespace rigdesign::deploy::nav2
