#pragma once
/// What a deployed ROS stack removes from one mount's data before its costmap sees it: nav2's
/// per-source range limits, laser_filters' angular bounds and boxes, pcl_ros crop boxes
/// (issue 14). `check` applies them to the coverage to measure what the deployment loses.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

/// A box whose inside is dropped: `min`..`max` in the box's own frame, placed by T_robot_box.
struct OrientedBox {
  Pose3 T_robot_box = Pose3::Identity();
  Vec3 min = Vec3::Zero();  ///< [m]
  Vec3 max = Vec3::Zero();  ///< [m]
};

/// Azimuths about the sensor's z axis (atan2(y, x) in the sensor frame, as a 2D scan's angles)
/// whose returns are dropped: those strictly between lower < upper [rad] (bounds may lie half a
/// ray step beyond +-pi, so that a band reaching the end of a scan includes its end ray).
struct AzimuthBand {
  double lower = 0.0;
  double upper = 0.0;
};

/// One setting that limits a mount, where it is written, for reports.
struct LimitSetting {
  std::string what;      ///< e.g. "obstacle_max_range 1.5 m", "angular bounds (-0.3, 0.3) rad"
  SourceLocation where;  ///< file:line:column of the setting
};

struct MountLimits {
  std::optional<double> min_range;  ///< [m] returns nearer the sensor origin are dropped
  std::optional<double> max_range;  ///< [m] returns farther are dropped
  std::vector<AzimuthBand> excluded_azimuths;
  std::vector<OrientedBox> excluded_boxes;

  bool empty() const {
    return !min_range && !max_range && excluded_azimuths.empty() && excluded_boxes.empty();
  }
};

}  // namespace rigdesign::model
