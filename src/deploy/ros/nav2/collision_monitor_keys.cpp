#include "deploy/ros/nav2/collision_monitor_keys.hpp"

namespace rigdesign::deploy::nav2 {

// use_sim_time is rclcpp's own parameter, in most nav2 parameter files.
const CollisionMonitorKeys kMonitorNodeKeys = {
    {"base_frame_id", "polygons", "observation_sources"},
    {"cmd_vel_in_topic", "cmd_vel_out_topic", "state_topic", "odom_frame_id", "transform_tolerance",
     "source_timeout", "base_shift_correction", "stop_pub_timeout", "use_realtime_priority",
     "enable_stamped_cmd_vel", "use_sim_time"}};

const CollisionMonitorKeys kMonitorPolygonKeys = {
    {"type", "action_type", "enabled", "points", "radius", "sources_names"},
    {"max_points", "min_points", "slowdown_ratio", "linear_limit", "angular_limit",
     "time_before_collision", "simulation_time_step", "visualize", "polygon_pub_topic",
     "footprint_topic", "polygon_sub_topic", "polygon_subscribe_transient_local",
     "velocity_polygons", "holonomic"}};

const CollisionMonitorKeys kMonitorSourceKeys = {
    {"type", "topic", "enabled", "min_height", "max_height", "min_range"},
    {"source_timeout", "use_global_height", "obstacles_angle", "sampling_distance"}};

}  // namespace rigdesign::deploy::nav2
