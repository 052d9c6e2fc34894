#pragma once
/// The occupancy sweep's trade-off (issue 6): F2 near the person against the ghost area over
/// the whole cell, each configuration coloured by its milliseconds per update; the
/// configurations no other beats on all three are ringed. PNG or SVG by extension.
#include <string>
#include <vector>

namespace rigdesign::render {

struct ParetoPoint {
  std::string label;        ///< e.g. "0.1 m, hit 3/1500"
  double f2 = 0.0;          ///< mean F2 near the person
  double ghost_area = 0.0;  ///< [m^2] mean ghost area
  double update_ms = 0.0;   ///< [ms] mean time per update
};

/// Indices of the points no other point beats or equals on every measure while beating it on
/// one (higher F2, lower ghost area, lower time). NaN F2 counts as worst.
std::vector<std::size_t> pareto_front(const std::vector<ParetoPoint>& points);

void plot_occupancy_pareto(const std::vector<ParetoPoint>& points, const std::string& title,
                           const std::string& path, int width = 1000, int height = 700);

}  // namespace rigdesign::render
