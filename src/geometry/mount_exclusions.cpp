#include "rigdesign/geometry/mount_exclusions.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/model/line_crossings.hpp"

namespace rigdesign::geometry {
namespace {

bool inside(const model::OrientedBox& box, const model::Vec3& p_robot) {
  const model::Vec3 q = box.T_robot_box.inverse() * p_robot;
  return (q.array() >= box.min.array()).all() && (q.array() <= box.max.array()).all();
}

// The parameters at which the line crosses one of the box's six planes.
void append_box_roots(const model::OrientedBox& box, const model::Vec3& start,
                      const model::Vec3& direction, std::vector<double>& roots) {
  const model::Vec3 c = box.T_robot_box.inverse() * start;
  const model::Vec3 w = box.T_robot_box.linear().transpose() * direction;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(w[axis]) < 1e-15) continue;
    roots.push_back((box.min[axis] - c[axis]) / w[axis]);
    roots.push_back((box.max[axis] - c[axis]) / w[axis]);
  }
}

}  // namespace

MountExclusions::MountExclusions(const model::MountLimits& limits,
                                 const model::Pose3& T_robot_sensor)
    : bands_(limits.excluded_azimuths),
      boxes_(limits.excluded_boxes),
      R_sensor_robot_(T_robot_sensor.linear().transpose()),
      origin_(T_robot_sensor.translation()) {}

bool MountExclusions::in_band(const model::Vec3& q) const {
  if (q.x() == 0.0 && q.y() == 0.0) return false;  // on the axis: no azimuth
  const double azimuth = std::atan2(q.y(), q.x());
  return std::any_of(bands_.begin(), bands_.end(), [&](const model::AzimuthBand& band) {
    return azimuth > band.lower && azimuth < band.upper;
  });
}

bool MountExclusions::excludes(const model::Vec3& p_robot) const {
  if (in_band(R_sensor_robot_ * (p_robot - origin_))) return true;
  return std::any_of(boxes_.begin(), boxes_.end(),
                     [&](const model::OrientedBox& box) { return inside(box, p_robot); });
}

IntervalSet MountExclusions::excluded_along(const model::Vec3& start, const model::Vec3& direction,
                                            double t_min, double t_max) const {
  IntervalSet excluded;
  if (empty() || !(t_max > t_min)) return excluded;
  std::vector<double> cuts = {t_min, t_max};
  const model::Vec3 c = R_sensor_robot_ * (start - origin_);
  const model::Vec3 w = R_sensor_robot_ * direction;
  for (const model::AzimuthBand& band : bands_) {
    for (const double angle : {band.lower, band.upper}) {
      // The half-plane at `angle` lies in the plane through the z axis with this normal.
      model::append_plane_crossing(model::Vec3(-std::sin(angle), std::cos(angle), 0.0), c, w, cuts);
    }
  }
  for (const model::OrientedBox& box : boxes_) append_box_roots(box, start, direction, cuts);
  for_each_piece(cuts, t_min, t_max, [&](double low, double high) {
    if (excludes(start + 0.5 * (low + high) * direction)) excluded.append(low, high);
  });
  return excluded;
}

}  // namespace rigdesign::geometry
