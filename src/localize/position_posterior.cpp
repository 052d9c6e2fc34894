#include "rigdesign/localize/position_posterior.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rigdesign::localize {

model::Vec2 PositionPosterior::centre(int column, int row) const {
  return origin + cell * model::Vec2(column + 0.5, row + 0.5);
}

int PositionPosterior::index_of(const model::Vec2& point) const {
  const double u = std::floor((point.x() - origin.x()) / cell);
  const double v = std::floor((point.y() - origin.y()) / cell);
  if (!(u >= 0 && v >= 0 && u < columns && v < rows)) return -1;
  return static_cast<int>(v) * columns + static_cast<int>(u);
}

bool PositionPosterior::contains(const model::Vec2& point) const {
  const int index = index_of(point);
  return index >= 0 && log_density[static_cast<std::size_t>(index)] >= threshold;
}

double PositionPosterior::credible_level(const model::Vec2& point) const {
  const int index = index_of(point);
  if (index < 0) return 1.0;
  const double own = log_density[static_cast<std::size_t>(index)];
  if (!std::isfinite(own)) return 1.0;
  double mass = 0.0;
  for (const double value : log_density)
    if (value > own) mass += std::exp(value - log_total) * cell * cell;
  return mass;
}

PositionPosterior make_posterior(const model::Vec2& origin, double cell, int columns, int rows,
                                 std::vector<double> log_density, double credible_mass) {
  PositionPosterior posterior;
  posterior.origin = origin;
  posterior.cell = cell;
  posterior.columns = columns;
  posterior.rows = rows;
  posterior.credible_mass = credible_mass;
  const double best = *std::max_element(log_density.begin(), log_density.end());
  std::vector<std::size_t> order(log_density.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return log_density[a] > log_density[b]; });
  double total = 0.0;
  for (const double v : log_density)
    if (std::isfinite(v)) total += std::exp(v - best);
  // The densest cells until they hold the credible mass.
  double accumulated = 0.0;
  posterior.threshold = best;
  for (const std::size_t i : order) {
    if (!std::isfinite(log_density[i])) break;
    accumulated += std::exp(log_density[i] - best);
    posterior.threshold = log_density[i];
    if (accumulated >= credible_mass * total) break;
  }
  posterior.log_total = best + std::log(total * cell * cell);
  posterior.log_density = std::move(log_density);
  return posterior;
}

double PositionPosterior::mass_within(const model::Vec2& point, double radius) const {
  double mass = 0.0;
  const int reach = static_cast<int>(std::ceil(radius / cell)) + 1;
  const model::Vec2 offset = (point - origin) / cell;
  const int c0 = static_cast<int>(std::floor(offset.x())),
            r0 = static_cast<int>(std::floor(offset.y()));
  for (int r = std::max(0, r0 - reach); r <= std::min(rows - 1, r0 + reach); ++r) {
    for (int c = std::max(0, c0 - reach); c <= std::min(columns - 1, c0 + reach); ++c) {
      const double value = log_density[static_cast<std::size_t>(r) * columns + c];
      if (value == -std::numeric_limits<double>::infinity()) continue;
      if ((centre(c, r) - point).norm() > radius) continue;
      mass += std::exp(value - log_total) * cell * cell;
    }
  }
  return mass;
}

}  // namespace rigdesign::localize
