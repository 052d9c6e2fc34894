#include "rigdesign/localize/object_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace rigdesign::localize {
namespace {

// A ring's Gaussian profile is cut where it has fallen to e^-8 (4 sigma): beyond, the mask
// is its floor to within 1 %. Inside, log(floor + (1 - floor) e^-x) comes from a table.
constexpr double kCut = 8.0;
constexpr int kTableSize = 4096;

class RingProfile {
 public:
  explicit RingProfile(double floor) : log_floor_(std::log(floor)) {
    for (int i = 0; i <= kTableSize; ++i) {
      const double x = kCut * i / kTableSize;
      table_[static_cast<std::size_t>(i)] =
          std::log(floor + (1 - floor) * std::exp(-x)) - log_floor_;
    }
  }
  /// log(mask) - log(floor) at x = (distance off the ring)^2 / (2 sigma^2) < kCut.
  double operator()(double x) const {
    const double position = x * (kTableSize / kCut);
    const auto i = static_cast<std::size_t>(position);
    const double f = position - static_cast<double>(i);
    return table_[i] + f * (table_[i + 1] - table_[i]);
  }
  double log_floor() const { return log_floor_; }

 private:
  double log_floor_;
  std::array<double, kTableSize + 1> table_{};
};

}  // namespace

ObjectMapResult object_map(const std::vector<Chunk>& chunks, const GeometryAnalysis& geometry,
                           const PathLossParams& path_loss, const ObjectMapParams& params) {
  ObjectMapResult result;
  if (chunks.empty()) return result;
  model::Vec2 low = model::Vec2::Constant(1e300), high = model::Vec2::Constant(-1e300);
  for (const Chunk& chunk : chunks) {
    low = low.cwiseMin(chunk.position().head<2>());
    high = high.cwiseMax(chunk.position().head<2>());
  }
  low.array() -= params.margin;
  high.array() += params.margin;
  ObjectMap& map = result.map;
  map.cell = params.cell;
  const model::Vec2 extent = high - low;
  // At most max_cells in all, also when the path is long and thin (one row of cells).
  map.cell = std::max({map.cell, std::sqrt(extent.x() * extent.y() / params.max_cells),
                       extent.maxCoeff() / params.max_cells});
  map.origin = low;
  map.width = static_cast<int>(std::ceil(extent.x() / map.cell));
  map.height = static_cast<int>(std::ceil(extent.y() / map.cell));
  map.log_probability.assign(static_cast<std::size_t>(map.width) * map.height, 0.0);
  // Every mask contributes log(floor) everywhere, a constant the map does not need: only
  // the cells within 4 sigma of a ring get its excess over the floor.
  const RingProfile profile(params.floor);
  for (const Chunk& chunk : chunks) {
    const model::Vec2 p = chunk.position().head<2>();
    const double r = chunk.mean_range();
    const double sigma = std::max(params.ring_sigma_min, params.ring_sigma_share * r);
    const double inverse = 1.0 / (2 * sigma * sigma);
    const double band = sigma * std::sqrt(2 * kCut);
    const double inner = std::max(0.0, r - band), outer = r + band;
    const double inner2 = inner * inner, outer2 = outer * outer;
    for (int j = 0; j < map.height; ++j) {
      const double dy = map.origin.y() + (j + 0.5) * map.cell - p.y();
      if (dy * dy >= outer2) continue;
      double* row = map.log_probability.data() + static_cast<std::size_t>(j) * map.width;
      for (int i = 0; i < map.width; ++i) {
        const double dx = map.origin.x() + (i + 0.5) * map.cell - p.x();
        const double d2 = dx * dx + dy * dy;
        if (d2 >= outer2 || d2 <= inner2) continue;
        const double off = std::sqrt(d2) - r;
        const double x = off * off * inverse;
        if (x < kCut) row[i] += profile(x);
      }
    }
  }
  const auto best = std::max_element(map.log_probability.begin(), map.log_probability.end());
  const double peak = *best;
  const auto best_index = static_cast<int>(best - map.log_probability.begin());
  const auto centre = [&](int i, int j) {
    return model::Vec2(map.origin.x() + (i + 0.5) * map.cell,
                       map.origin.y() + (j + 0.5) * map.cell);
  };
  Hypothesis& estimate = result.estimate;
  estimate.position << centre(best_index % map.width, best_index / map.width),
      geometry.centroid.z();
  estimate.rssi_at_1m_dbm = path_loss.rssi_at_1m_dbm;
  estimate.exponent = path_loss.exponent;
  estimate.cost = -peak;
  // Covariance of the normalised map about the estimate.
  double total = 0.0;
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  std::size_t index = 0;
  for (int j = 0; j < map.height; ++j) {
    for (int i = 0; i < map.width; ++i, ++index) {
      const double p = std::exp(map.log_probability[index] - peak);
      if (p < 1e-12) continue;
      const model::Vec2 offset = centre(i, j) - estimate.position.head<2>();
      total += p;
      second += p * offset * offset.transpose();
    }
  }
  estimate.covariance.topLeftCorner<2, 2>() = second / total;
  return result;
}

}  // namespace rigdesign::localize
