#pragma once
// nav2 collision_monitor's parameter names as deploy/ros/nav2/collision_monitor_reader.cpp reads
// them: the keys it models and the keys it reads past, per level (node, polygon, source). Every
// name is one nav2 declares in Humble or Jazzy (data/ros_parameters/nav2_collision_monitor.yaml;
// tests/deploy/ros_declared_keys_test.cpp holds the lists to it).
#include <string>
#include <vector>

namespace rigdesign::deploy::nav2 {

struct CollisionMonitorKeys {
  std::vector<std::string> modelled;
  std::vector<std::string> ignored;
};

extern const CollisionMonitorKeys kMonitorNodeKeys;
extern const CollisionMonitorKeys kMonitorPolygonKeys;
extern const CollisionMonitorKeys kMonitorSourceKeys;

}  // namespace rigdesign::deploy::nav2
