#pragma once
/// The regions a deployed stack's filters drop from one mount's data (model::MountLimits'
/// azimuth bands and boxes), as exact sets along a line: a band is bounded by two half-planes
/// through the sensor's z axis and a box by six planes, so every place where a line enters or
/// leaves them is a linear root, and each piece between roots is tested once.
#include "rigdesign/geometry/interval_set.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/mount_limits.hpp"

namespace rigdesign::geometry {

class MountExclusions {
 public:
  MountExclusions(const model::MountLimits& limits, const model::Pose3& T_robot_sensor);

  /// True when a return at `p_robot` is dropped.
  bool excludes(const model::Vec3& p_robot) const;

  /// The parameters t in [t_min, t_max] at which start + t * direction (robot frame) is dropped.
  IntervalSet excluded_along(const model::Vec3& start, const model::Vec3& direction, double t_min,
                             double t_max) const;

  bool empty() const { return bands_.empty() && boxes_.empty(); }

 private:
  bool in_band(const model::Vec3& q_sensor) const;
  std::vector<model::AzimuthBand> bands_;
  std::vector<model::OrientedBox> boxes_;
  model::Mat3 R_sensor_robot_;
  model::Vec3 origin_;
};

}  // namespace rigdesign::geometry
