#pragma once
/// `self_filters.launch.py`, as `rigdesign export` writes it (issue 30 item 5): a ROS 2 Python
/// launch file that starts every self-filter of self_filters.yaml on the driver's topic and
/// publishes where the exported nav2 sources subscribe. Per 2D scanner a laser_filters
/// `scan_to_scan_filter_chain` node `<mount>_self_filter` (scan -> scan_filtered remapped);
/// per 3D sensor a chain of pcl_ros `pcl_ros::CropBox` components `<mount>_self_filter_<k>`
/// (input -> output remapped, each reading the previous one's output) in one container.
/// Node names equal the parameter file's keys, so each node finds its parameters; executables,
/// plugins and topic names are those of data/ros_parameters/laser_filters_pcl_ros.yaml.
#include <string>
#include <vector>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/self_filters.hpp"

namespace rigdesign::deploy {

/// `sources` parallel to `filters` (mount order) give each mount's raw and filtered topics;
/// `params_file` is the parameter file's name beside the launch file.
std::string self_filters_launch_text(const std::vector<deploy::SelfFilter>& filters,
                                     const std::vector<deploy::SourceConfig>& sources,
                                     const std::string& params_file, const std::string& header);

}  // namespace rigdesign::deploy
