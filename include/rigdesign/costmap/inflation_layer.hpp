#pragma once
/// The inflation layer with nav2's cost values (nav2 InflationLayer::computeCost): lethal
/// cells stay 254, cells whose centre lies within the inscribed radius of a lethal cell's
/// centre get 253, cells farther but within the inflation radius get
/// 252 exp(-k (d - r_inscribed)), truncated to an integer as nav2 does. Distances come from an
/// exact Euclidean distance transform (Felzenszwalb and Huttenlocher 2012) over the whole
/// window, not nav2's breadth-first wave: the same values where nav2's wave finds the nearest
/// lethal cell, and linear time whatever the radius.
#include <cstdint>
#include <span>
#include <vector>

#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::costmap {

struct InflationParams {
  double inscribed_radius =
      0.1;  ///< [m] the footprint's inscribed radius (nav2 robot_radius default)
  double inflation_radius = 0.55;  ///< [m] nav2's default
  /// k [1/m]: nav2_bringup's configured 3.0 (nav2's code default is 1.0).
  double cost_scaling_factor = 3.0;
  /// nav2's `inflate_unknown`: when false an unknown cell only takes costs >= 253.
  bool inflate_unknown = false;
};

/// nav2's cost of a cell whose centre lies `distance` [m] from the nearest lethal cell's centre:
/// 254 at 0, 253 up to the inscribed radius, 252 exp(-k (d - r_inscribed)) up to the inflation
/// radius (truncated), 0 beyond.
std::uint8_t inflation_cost(double distance, const InflationParams& params);

/// Squared Euclidean distance, in cells squared, from each cell's centre to the nearest
/// source cell's centre (a very large value when there is none). `is_source` and the output
/// are row-major width x height. Exact; O(width x height).
void squared_distance_transform(std::span<const std::uint8_t> is_source, int width, int height,
                                std::vector<double>& squared_distance);

class InflationLayer {
 public:
  explicit InflationLayer(const InflationParams& params = {}) : params_(params) {}

  /// Inflates `master` in place around its cost::kLethal cells: every cell takes the larger
  /// of its cost and inflation_cost(d); an unknown cell keeps cost::kUnknown unless the new
  /// cost is >= 253 (or > 0 with inflate_unknown), as in nav2.
  void apply(CostGrid& master);

  const InflationParams& params() const { return params_; }
  /// Squared distances (cells squared) of the last apply, for scoring and drawing.
  const std::vector<double>& squared_distances() const { return squared_; }

 private:
  InflationParams params_;
  double table_resolution_ = 0.0;
  std::vector<std::uint8_t> cost_by_squared_cells_;  // nav2's cost cache, keyed by d^2 in cells
  std::vector<std::uint8_t> sources_;
  std::vector<double> squared_;
};

}  // namespace rigdesign::costmap
