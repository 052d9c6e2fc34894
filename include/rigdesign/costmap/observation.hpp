#pragma once
/// One sensor's cloud as the costmap layers take it, with that source's nav2-style flags and
/// ranges (nav2 ObstacleLayer's observation source parameters).
#include <string>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::costmap {

/// Per-source settings. Defaults are nav2's except min_obstacle_height (see its comment).
struct ObservationSource {
  bool marking = true;              ///< its end points mark obstacles
  bool clearing = true;             ///< its rays clear the space they cross
  double obstacle_min_range = 0.0;  ///< [m] end points nearer the sensor origin do not mark
  double obstacle_max_range = 2.5;  ///< [m] end points farther do not mark
  double raytrace_min_range = 0.0;  ///< [m] clearing starts this far along each ray
  double raytrace_max_range = 3.0;  ///< [m] clearing stops this far along each ray
  /// [m] world z band of points that mark. nav2's default minimum is 0.0 and assumes the
  /// floor was removed upstream; 5 cm keeps the returns of a floor with centimetre range
  /// noise out of the grid, while paper 2's negative-obstacle points (10 cm) still mark.
  double min_obstacle_height = 0.05;
  double max_obstacle_height = 2.0;
  /// [s] nav2's `observation_persistence`: each cloud of this source keeps marking (and
  /// clearing) from where it was taken until it is this much older than the update; 0 keeps
  /// only the newest cloud. How an exported rig remembers what enters a blind gap
  /// (deploy/blind_memory.hpp).
  double observation_persistence = 0.0;

  bool operator==(const ObservationSource&) const = default;

  /// Whether a world-frame z lies in the [min, max]_obstacle_height band.
  bool in_height_band(double z_world) const {
    return z_world >= min_obstacle_height && z_world <= max_obstacle_height;
  }
  /// Whether an end point marks: in the height band, and its distance from the sensor origin
  /// within [obstacle_min_range, obstacle_max_range]. The 2D and 3D layers share this rule.
  bool marks(const model::Vec3& p_world, const model::Vec3& origin_world) const {
    const double squared = (p_world - origin_world).squaredNorm();
    return in_height_band(p_world.z()) && squared >= obstacle_min_range * obstacle_min_range &&
           squared <= obstacle_max_range * obstacle_max_range;
  }
};

/// A source as nav2 names it in `observation_sources` (rigdesign names them after mounts).
struct NamedObservationSource {
  std::string name;
  ObservationSource source;
};

/// A cloud in any frame and the transform to the world; the cloud's `origin` is the sensor
/// origin in the cloud's frame (PointCloud's VIEWPOINT), where every ray starts.
struct CloudObservation {
  const model::PointCloud* cloud = nullptr;  ///< not owned; must outlive the update call
  /// Maps cloud-frame points into the world frame: T_world_robot for robot-frame clouds,
  /// identity for world-frame ones.
  model::Pose3 T_world_cloud = model::Pose3::Identity();
  ObservationSource source;
};

}  // namespace rigdesign::costmap
