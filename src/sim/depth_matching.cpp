// A window-matching depth camera's return along one pixel's ray (issue 54 item 1).
#include "rigdesign/sim/depth_matching.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rigdesign::sim {
namespace {

constexpr int kSamples = 9;  // the window as a 3 x 3 grid, the centre first
constexpr int kMajority = 5;

// Whether ranges `a` and `b` [m] are one surface to the matcher: disparities (baseline_focal
// over depth) less than a pixel apart, |a - b| < a^2 / baseline_focal for a ~ b.
bool same_surface(double a, double b, double baseline_focal) {
  if (!std::isfinite(a) || !std::isfinite(b)) return false;
  return std::abs(a - b) * baseline_focal < a * a;
}

}  // namespace

std::optional<double> window_majority(double centre, const std::function<double(int, int)>& sample,
                                      double baseline_focal) {
  std::array<double, kSamples> ranges{};
  ranges[0] = centre;
  std::size_t n = 1;
  for (int row = -1; row <= 1; ++row) {
    for (int column = -1; column <= 1; ++column) {
      if (row != 0 || column != 0) ranges[n++] = sample(row, column);
    }
  }
  // The centre's surface if it fills most of the window, else the first that does.
  for (const double candidate : ranges) {
    int agreeing = 0;
    for (const double other : ranges)
      agreeing += same_surface(candidate, other, baseline_focal) ? 1 : 0;
    if (agreeing >= kMajority) return candidate;
  }
  return std::nullopt;
}

std::optional<double> matched_range(const RayCaster& scene, const model::Vec3& origin,
                                    const model::Vec3& direction, const model::Vec3& up,
                                    double centre, const model::DepthMatching& matching,
                                    double free_range) {
  // The window's row runs along `left`, its column along `column_up`, both across the ray.
  model::Vec3 left = up.cross(direction);
  if (left.squaredNorm() < 1e-12) left = direction.unitOrthogonal();
  left.normalize();
  const model::Vec3 column_up = direction.cross(left);
  const double step = std::tan(matching.window_angle / 3.0);
  const auto cast = [&](int row, int column) {
    const model::Vec3 ray = (direction + step * (column * left + row * column_up)).normalized();
    const std::optional<double> hit = scene.first_hit(origin, ray);
    const double range = hit ? *hit : std::numeric_limits<double>::infinity();
    return std::min(range, free_range);  // beyond it, the robot's own surface
  };
  return window_majority(centre, cast, matching.baseline_focal);
}

}  // namespace rigdesign::sim
