#pragma once
/// `collision_monitor.yaml`, as `rigdesign export` writes it: the parameters of nav2's
/// collision_monitor node (https://docs.nav2.org/configuration/packages/
/// configuring-collision-monitor.html), keys and formats as nav2 declares them for the chosen
/// release (data/ros_parameters/nav2_collision_monitor.yaml): Jazzy writes polygon points as a
/// string "[[x, y], ...]", min_points and each polygon's sources_names; Humble a flat list of
/// numbers, max_points, and every source feeds every polygon. Read back by
/// deploy/ros/nav2/collision_monitor_reader.hpp for `check --collision-monitor`.
#include <string>

#include "rigdesign/deploy/collision_monitor.hpp"
#include "rigdesign/deploy/costmap_config.hpp"

namespace rigdesign::deploy {

/// The file's text; `header` opens it as comments, then how the zones were sized.
std::string collision_monitor_text(const deploy::CollisionMonitor& monitor,
                                   const deploy::CostmapConfig& config, const std::string& header);

}  // namespace rigdesign::deploy
