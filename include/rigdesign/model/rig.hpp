#pragma once
/// A rig: the robot body, the distance of interest and the mounted sensors (DESIGN.md
/// section 3). Frames follow REP-103: the robot frame is on the floor under the robot's
/// centre, x forward, y left, z up.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

/// The robot's body, which bounds the area to perceive (rho >= r, z in [0, h]) and occludes.
struct RobotBody {
  double height = 0.0;  ///< h [m]
  /// Cylinder radius r [m]; with a footprint it is the footprint's largest distance from
  /// the robot's vertical axis.
  double radius = 0.0;
  std::vector<Vec2> footprint;  ///< optional prism cross-section, counter-clockwise [m]
};

struct Mount {
  std::string id;
  std::string sensor_id;
  std::string mode_id;
  /// Maps sensor-frame points into the robot frame (sensor frame: x along the optical axis).
  Pose3 T_robot_sensor = Pose3::Identity();
  std::optional<double> distance_of_interest;  ///< [m] overrides the rig's for this mount
  SourceLocation where;                        ///< the mount's entry
  SourceLocation sensor_where;  ///< its `sensor` value, for findings about the reference
  SourceLocation mode_where;    ///< its `mode` value
  SourceLocation pose_where;    ///< its `pose`
};

struct Rig {
  std::string name;
  RobotBody body;
  double distance_of_interest = 0.0;  ///< d [m]
  std::vector<Mount> mounts;
  std::string sensor_library;  ///< path as written in the file (relative to it), may be empty
  std::string requirements;    ///< path as written in the file (relative to it), may be empty
  SourceLocation sensor_library_where;
  SourceLocation requirements_where;
  std::string file;
  SourceLocation where;

  /// The distance at which a mount's resolution and noise are judged [m].
  double distance_for(const Mount& mount) const {
    return mount.distance_of_interest.value_or(distance_of_interest);
  }
};

}  // namespace rigdesign::model
