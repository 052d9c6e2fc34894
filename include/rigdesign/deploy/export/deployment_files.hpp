#pragma once
/// The folder `rigdesign export` writes (issue 14): the sensors' URDF macro
/// (deploy/ros/description/sensors_xacro_writer.hpp), nav2's costmap parameters
/// (deploy/ros/nav2/costmap_params_writer.hpp) and the self-filters in the formats
/// laser_filters and pcl_ros read (deploy/ros/self_filters/self_filters_writer.hpp), each
/// written beside the computation that fills it.
#include <string>
#include <vector>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::deploy {

/// Writes sensors.urdf.xacro, nav2_costmap.yaml, self_filters.yaml (and its launch file),
/// sensors.gazebo.xacro and bridge.yaml into `folder` (created
/// if missing), each atomically; `header` opens every file. Returns the paths written.
/// Throws InputError when the folder cannot be written.
std::vector<std::string> write_deployment(const std::string& folder, const model::Rig& rig,
                                          const deploy::Deployment& deployment,
                                          const std::string& header);

}  // namespace rigdesign::deploy
