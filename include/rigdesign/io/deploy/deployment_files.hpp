#pragma once
/// The files `rigdesign export` writes (issue 14), as text: the sensors' URDF macro, nav2's
/// costmap parameters and the self-filters in the formats laser_filters and pcl_ros read.
#include <string>
#include <vector>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/self_filters.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

/// `sensors.urdf.xacro`: one macro, `<xacro:rig_sensors parent="..." prefix=""/>`, with a link
/// and fixed joint per mount and a camera's optical frame. Numbers are written so that they
/// read back exactly.
std::string sensors_xacro_text(const deploy::SensorFrames& frames, const std::string& header);

/// `nav2_costmap.yaml`: local_costmap and global_costmap parameter blocks as nav2 reads them
/// (https://docs.nav2.org/configuration/packages/configuring-costmaps.html), the Hit Layer's
/// keys under `hit_layer`.
std::string nav2_costmap_text(const deploy::CostmapConfig& config, const std::string& header);

/// `self_filters.yaml`: per 2D scanner a laser_filters `scan_to_scan_filter_chain` node named
/// `<mount>_self_filter` with one LaserScanAngularBoundsFilterInPlace per band; per 3D sensor
/// hitting its robot one pcl_ros CropBox node `<mount>_self_filter_<k>` per box (negative:
/// true drops the inside), in the frame `box_frame` whose pose in the robot frame is
/// T_robot_box_frame.
std::string self_filters_text(const std::vector<deploy::SelfFilter>& filters,
                              const std::string& box_frame, const model::Pose3& T_robot_box_frame,
                              const std::string& header);

/// Writes sensors.urdf.xacro, nav2_costmap.yaml and self_filters.yaml into `folder` (created
/// if missing), each atomically; `header` opens every file. Returns the paths written.
/// Throws InputError when the folder cannot be written.
std::vector<std::string> write_deployment(const std::string& folder, const model::Rig& rig,
                                          const deploy::Deployment& deployment,
                                          const std::string& header);

}  // namespace rigdesign::io
