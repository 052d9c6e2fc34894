#include "support/clouds.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace rigdesign::test {

model::PointCloud cloud_of(std::vector<model::Point3f> points) {
  model::PointCloud cloud;
  cloud.points = std::move(points);
  return cloud;
}

std::vector<model::Point3f> noisy_floor(double size, double spacing, double sigma,
                                        std::mt19937& rng) {
  std::normal_distribution<float> noise(0.0f, static_cast<float>(sigma));
  std::vector<model::Point3f> points;
  for (double x = -size / 2; x < size / 2; x += spacing) {
    for (double y = -size / 2; y < size / 2; y += spacing) {
      points.emplace_back(static_cast<float>(x), static_cast<float>(y), noise(rng));
    }
  }
  return points;
}

std::vector<std::uint32_t> brute_force_inliers(const std::vector<model::Point3f>& points, int k) {
  // Exact k nearest by a sweep along x (not a grid): the points in x order, each one's
  // neighbours scanned outwards on both sides until the x gap alone is no shorter than the
  // k-th distance found so far. Distances in double.
  if (points.empty()) return {};
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return points[a].x() < points[b].x(); });
  const auto wanted = std::min(points.size() - 1, static_cast<std::size_t>(k));
  std::vector<double> mean(points.size());
  for (std::size_t q = 0; q < order.size(); ++q) {
    const model::Point3f& p = points[order[q]];
    std::priority_queue<double> nearest;  // the k smallest so far, largest on top
    const auto consider = [&](std::size_t j) {
      // The gap as the distance below takes its x component (float), so it never exceeds it.
      const double gap = std::abs(static_cast<double>(points[order[j]].x() - p.x()));
      if (nearest.size() == wanted && gap >= nearest.top()) return false;
      const double d = (p - points[order[j]]).cast<double>().norm();
      if (nearest.size() < wanted) {
        nearest.push(d);
      } else if (d < nearest.top()) {
        nearest.pop();
        nearest.push(d);
      }
      return true;
    };
    for (std::size_t j = q; j-- > 0;) {
      if (!consider(j)) break;
    }
    for (std::size_t j = q + 1; j < order.size(); ++j) {
      if (!consider(j)) break;
    }
    double sum = 0;
    for (; !nearest.empty(); nearest.pop()) sum += nearest.top();
    mean[order[q]] = sum / static_cast<double>(wanted);
  }
  double sum = 0, squares = 0;
  for (const double m : mean) {
    sum += m;
    squares += m * m;
  }
  const double n = static_cast<double>(mean.size());
  const double threshold = sum / n + std::sqrt((squares - sum * sum / n) / (n - 1));
  std::vector<std::uint32_t> expected;
  for (std::uint32_t i = 0; i < mean.size(); ++i) {
    if (mean[i] <= threshold) expected.push_back(i);
  }
  return expected;
}

}  // namespace rigdesign::test
