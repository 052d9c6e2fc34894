#include "deploy/ros/nav2/nav2_keys.hpp"

namespace rigdesign::deploy::nav2 {

const std::vector<std::string> kIgnoredCostmapKeys = {
    "update_frequency",  "publish_frequency",        "global_frame",
    "robot_base_frame",  "rolling_window",           "always_send_full_costmap",
    "footprint_padding", "transform_tolerance",      "use_sim_time",
    "map_topic",         "lethal_cost_threshold",    "unknown_cost_value",
    "trinary_costmap",   "initial_transform_timeout"};

const std::vector<std::string> kIgnoredLayerKeys = {"plugin",
                                                    "enabled",
                                                    "publish_voxel_map",
                                                    "footprint_clearing_enabled",
                                                    "combination_method",
                                                    "max_obstacle_height",
                                                    "min_obstacle_height"};

const std::vector<std::string> kIgnoredSourceKeys = {"topic", "data_type", "sensor_frame",
                                                     "expected_update_rate", "inf_is_valid"};

const std::vector<std::string> kKnownLayerClasses = {
    "nav2_costmap_2d::InflationLayer",
    "nav2_costmap_2d::ObstacleLayer",
    "nav2_costmap_2d::StaticLayer",
    "nav2_costmap_2d::VoxelLayer",
    "nav2_costmap_2d::RangeSensorLayer",
    "nav2_costmap_2d::DenoiseLayer",
    "nav2_costmap_2d::PluginContainerLayer",
    "spatio_temporal_voxel_layer/SpatioTemporalVoxelLayer"};

const std::vector<std::pair<std::string, std::string>> kKeyOfField = {
    {"resolution", "resolution"},
    {"robot_radius", "robot_radius"},
    {"size_x", "width"},
    {"size_y", "height"},
    {"hit.hit", "hit_layer.hit"},
    {"hit.hit_max", "hit_layer.hit_max"},
    {"hit.d_threshold", "hit_layer.d_threshold"},
    {"hit.d_duration", "hit_layer.d_duration"},
    {"inflation.inflation_radius", "inflation_layer.inflation_radius"},
    {"inflation.cost_scaling_factor", "inflation_layer.cost_scaling_factor"},
    {"inflation.inscribed_radius", "robot_radius"},
    {"voxel.z_min", "voxel_layer.origin_z"},
    {"voxel.z_max", "voxel_layer.z_voxels"},
    {"voxel.z_resolution", "voxel_layer.z_resolution"},
    {"voxel.unknown_threshold", "voxel_layer.unknown_threshold"}};

}  // namespace rigdesign::deploy::nav2
