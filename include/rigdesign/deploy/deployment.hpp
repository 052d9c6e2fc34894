#pragma once
/// Everything a rig means for the ROS stack that runs it (issue 14): sensor frames, nav2
/// costmap parameters, self-filters, Gazebo sensors. `rigdesign export` and `select --out` write
/// it.
#include <optional>
#include <vector>

#include "rigdesign/deploy/collision_monitor.hpp"
#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/gazebo_sensors.hpp"
#include "rigdesign/deploy/self_filters.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/deploy/stvl_config.hpp"

namespace rigdesign::deploy {

struct Deployment {
  SensorFrames frames;
  CostmapConfig costmap;
  std::vector<SelfFilter> self_filters;
  std::vector<GazeboSensor> gazebo;  ///< the rig in gz sim (issue 34)
  std::optional<StvlLayer> stvl;     ///< DeployOptions::stvl: the 3D sources in STVL
  /// nav2's collision monitor; nothing without a robot speed (requirements R5 or --max-speed).
  std::optional<CollisionMonitor> collision_monitor;
};

/// Precondition: the rig's references resolve in `library`. `requirements` may be null.
/// Throws InputError for a `parent` that is not a link of the rig (sensor_frames).
Deployment plan_deployment(const model::Rig& rig, const model::SensorLibrary& library,
                           const model::Requirements* requirements, const DeployOptions& options);

}  // namespace rigdesign::deploy
