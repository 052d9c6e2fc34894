#include "rigdesign/geometry/cross_section.hpp"

#include <cmath>

namespace rigdesign::geometry {

model::Vec3 SectionFrame::point(double rho, double z) const {
  return {rho * std::cos(theta), rho * std::sin(theta), z};
}

SectionFrame section_frame(const BodyOccluder& body, double theta, double distance_of_interest) {
  return {theta, body.radius_at(theta), distance_of_interest, body.area_top()};
}

IntervalSet column_coverage(const MountedFov& fov, const SectionFrame& frame, double rho) {
  return fov.covered_along(frame.point(rho, 0.0), model::Vec3::UnitZ(), 0.0, frame.h, frame.theta);
}

IntervalSet floor_coverage(const MountedFov& fov, const SectionFrame& frame) {
  const model::Vec3 outward(std::cos(frame.theta), std::sin(frame.theta), 0.0);
  return fov.covered_along(model::Vec3::Zero(), outward, frame.r, frame.d, frame.theta);
}

}  // namespace rigdesign::geometry
