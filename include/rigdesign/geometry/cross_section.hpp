#pragma once
/// The cross-section at azimuth theta (paper 1, section 2.3; DESIGN.md section 4): the
/// vertical half-plane through the robot's vertical axis, restricted to rho in [r, d] and
/// z in [0, h]. Coordinates in it are (rho, z).
#include "rigdesign/geometry/interval_set.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"

namespace rigdesign::geometry {

struct SectionFrame {
  double theta = 0.0;  ///< [rad] azimuth, counter-clockwise from x
  double r = 0.0;      ///< [m] body radius along theta (the cylinder's r, or the footprint's)
  double d = 0.0;      ///< [m] distance of interest
  double h = 0.0;      ///< [m] body height

  double width() const { return d - r; }
  double area() const { return (d - r) * h; }
  /// Robot-frame point of section coordinates (rho, z).
  model::Vec3 point(double rho, double z) const;
};

SectionFrame section_frame(const BodyOccluder& body, double theta, double distance_of_interest);

/// The z intervals in [0, h] that `fov` sees on the vertical line rho = `rho`.
IntervalSet column_coverage(const MountedFov& fov, const SectionFrame& frame, double rho);

/// The rho intervals in [r, d] that `fov` sees on the floor line z = 0.
IntervalSet floor_coverage(const MountedFov& fov, const SectionFrame& frame);

}  // namespace rigdesign::geometry
