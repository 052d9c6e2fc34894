#include "rigdesign/costmap/inflation_layer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {
namespace {

// "No source": far beyond any squared distance in a window (and exact in a double), so the
// parabola intersections below stay finite.
constexpr double kFar = 1e12;

// Felzenszwalb and Huttenlocher's 1D squared distance transform of the sampled function f:
// out[q] = min_p (q - p)^2 + f[p], by the lower envelope of parabolas. `v` and `z` are scratch.
void transform_line(const double* f, int n, double* out, std::vector<int>& v,
                    std::vector<double>& z) {
  v.resize(static_cast<std::size_t>(n));
  z.resize(static_cast<std::size_t>(n) + 1);
  const auto square = [](int q) { return static_cast<double>(q) * q; };
  int k = 0;
  v[0] = 0;
  z[0] = -kFar;
  z[1] = kFar;
  for (int q = 1; q < n; ++q) {
    // |s| stays below kFar / 2 (f differs by at most kFar, divided by at least 2), so the
    // sentinel z[0] = -kFar is never passed.
    const auto intersection = [&](int p) {
      return ((f[q] + square(q)) - (f[p] + square(p))) / (2.0 * (q - p));
    };
    double s = intersection(v[k]);
    while (s <= z[k]) s = intersection(v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kFar;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    out[q] = square(q - v[k]) + f[v[k]];
  }
}

}  // namespace

std::uint8_t inflation_cost(double distance, const InflationParams& params) {
  if (distance <= 0.0) return cost::kLethal;
  if (distance <= params.inscribed_radius) return cost::kInscribed;
  if (distance > params.inflation_radius) return cost::kFree;
  const double factor =
      std::exp(-params.cost_scaling_factor * (distance - params.inscribed_radius));
  return static_cast<std::uint8_t>(cost::kMaxNonObstacle * factor);  // truncated, as nav2 casts
}

void squared_distance_transform(std::span<const std::uint8_t> is_source, int width, int height,
                                std::vector<double>& squared_distance) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (is_source.size() != n)
    throw std::invalid_argument("squared_distance_transform: size mismatch");
  squared_distance.assign(n, kFar);
  if (n == 0) return;
  // Pass 1, along y: distance to the nearest source in the same column, by a sweep up and a
  // sweep down over whole rows at once (contiguous memory).
  std::vector<double> column(n);
  const auto w = static_cast<std::size_t>(width);
  for (int y = 0; y < height; ++y) {
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      column[i] = is_source[i] ? 0.0 : (y > 0 ? column[i - w] + 1.0 : kFar);
    }
  }
  for (int y = height - 2; y >= 0; --y) {
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      column[i] = std::min(column[i], column[i + w] + 1.0);
    }
  }
  for (double& d : column) d = d >= kFar / 2 ? kFar : d * d;
  // Pass 2, along x: the exact 2D result from the column distances.
  std::vector<int> v;
  std::vector<double> z;
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    transform_line(column.data() + row, width, squared_distance.data() + row, v, z);
  }
}

void InflationLayer::apply(CostGrid& master) {
  const GridWindow& window = master.window();
  if (table_resolution_ != window.resolution) {
    // Squared cell distances are integers; cache nav2's cost for each up to the radius.
    const auto reach = static_cast<int>(std::ceil(params_.inflation_radius / window.resolution));
    cost_by_squared_cells_.assign(static_cast<std::size_t>(reach) * reach + 1, cost::kFree);
    for (std::size_t k = 0; k < cost_by_squared_cells_.size(); ++k) {
      cost_by_squared_cells_[k] =
          inflation_cost(std::sqrt(static_cast<double>(k)) * window.resolution, params_);
    }
    table_resolution_ = window.resolution;
  }
  std::vector<std::uint8_t>& cells = master.cells();
  sources_.resize(cells.size());
  std::transform(cells.begin(), cells.end(), sources_.begin(),
                 [](std::uint8_t c) { return static_cast<std::uint8_t>(c == cost::kLethal); });
  squared_distance_transform(sources_, window.width, window.height, squared_);
  const double last = static_cast<double>(cost_by_squared_cells_.size() - 1);
  const std::uint8_t unknown_floor = params_.inflate_unknown ? 1 : cost::kInscribed;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (squared_[i] > last) continue;
    const std::uint8_t inflated = cost_by_squared_cells_[static_cast<std::size_t>(squared_[i])];
    std::uint8_t& cell = cells[i];
    if (cell == cost::kUnknown) {
      if (inflated >= unknown_floor) cell = inflated;  // nav2's rule for unknown cells
    } else {
      cell = std::max(cell, inflated);
    }
  }
}

}  // namespace rigdesign::costmap
