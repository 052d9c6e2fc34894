#pragma once
/// `self_filters.yaml`, as `rigdesign export` writes it: per 2D scanner a laser_filters
/// `scan_to_scan_filter_chain` node named `<mount>_self_filter` with one
/// LaserScanAngularBoundsFilterInPlace per band; per 3D sensor hitting its robot one pcl_ros
/// CropBox node `<mount>_self_filter_<k>` per box (negative: true drops the inside), in the
/// frame `box_frame` whose pose in the robot frame is T_robot_box_frame. Read back by
/// deploy/ros/self_filters/self_filters_reader.hpp.
#include <string>
#include <vector>

#include "rigdesign/deploy/self_filters.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::deploy {

/// The file's text; `header` opens it as comments.
std::string self_filters_text(const std::vector<deploy::SelfFilter>& filters,
                              const std::string& box_frame, const model::Pose3& T_robot_box_frame,
                              const std::string& header);

}  // namespace rigdesign::deploy
