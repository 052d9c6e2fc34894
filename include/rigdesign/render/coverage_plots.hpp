#pragma once
/// Spatial Coverage curves as pictures (PNG or SVG by the file extension), drawn with Cairo.
#include <string>

#include "rigdesign/metrics/coverage.hpp"

namespace rigdesign::render {

/// SC complete and floor (and redundancy) against theta in degrees, with every requirement
/// sector's thresholds drawn over its angles.
void plot_sc_cartesian(const metrics::RigCoverage& coverage, const std::string& rig_name,
                       const std::string& path, int width = 1200, int height = 620);

/// The same curves around the robot seen from above: forward (theta = 0) up, left (90 deg)
/// to the left; the radius is the coverage share.
void plot_sc_polar(const metrics::RigCoverage& coverage, const std::string& rig_name,
                   const std::string& path, int size = 900);

/// Where draw_section puts the section: equal scales on both axes.
struct SectionLayout {
  int width = 0;
  int height = 0;
  double left = 0.0;    ///< [px] x of rho = 0
  double bottom = 0.0;  ///< [px] y of z = 0
  double scale = 0.0;   ///< [px/m]
  double x(double rho) const { return left + rho * scale; }
  double y(double z) const { return bottom - z * scale; }
};

SectionLayout section_layout(const geometry::SectionFrame& frame, std::size_t sensors,
                             int width = 1200, int max_height = 800);

/// A cross-section: each sensor's region in its colour (overlaps show through), the
/// [r, d] x [0, h] frame, the body, the covered floor, axes in metres. Equal scales on both
/// axes: the height follows the section's aspect, up to `max_height`.
void draw_section(const metrics::SectionView& view, const std::string& rig_name,
                  const std::string& path, int width = 1200, int max_height = 800);

}  // namespace rigdesign::render
