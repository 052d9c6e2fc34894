#pragma once
/// Paper 4's object map: a probability grid in the robot's plane, multiplied per chunk by a
/// ring mask (high at the chunk's distance from RSSI, blurred by a Gaussian), its maximum being
/// the estimate. Kept for comparison with the range fit. Products are sums of logarithms so
/// thousands of masks do not underflow.
#include <vector>

#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/localize/geometry_analysis.hpp"
#include "rigdesign/localize/hypothesis.hpp"
#include "rigdesign/localize/path_loss.hpp"

namespace rigdesign::localize {

struct ObjectMapParams {
  double cell = 0.5;              ///< grid cell [m]
  double margin = 15.0;           ///< the grid extends this far beyond the chunks [m]
  double ring_sigma_min = 0.5;    ///< blur of a ring [m], at least
  double ring_sigma_share = 0.2;  ///< blur as a share of the ring's radius (ranges from RSSI
                                  ///< err in proportion to the range)
  double floor = 0.05;            ///< a mask never drops below this, so no ring vetoes a cell
  int max_cells = 1000000;        ///< the cell grows when the area would need more cells
};

struct ObjectMap {
  model::Vec2 origin = model::Vec2::Zero();  ///< corner of cell (0, 0) [m]
  double cell = 0.5;                         ///< [m]
  int width = 0, height = 0;
  std::vector<double> log_probability;  ///< row-major, up to a constant
};

struct ObjectMapResult {
  ObjectMap map;
  Hypothesis estimate;  ///< the most probable cell's centre; covariance of the normalised map
};

/// Empty map (width 0) when there are no chunks.
ObjectMapResult object_map(const std::vector<Chunk>& chunks, const GeometryAnalysis& geometry,
                           const PathLossParams& path_loss, const ObjectMapParams& params = {});

}  // namespace rigdesign::localize
