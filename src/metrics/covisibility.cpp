#include "rigdesign/metrics/covisibility.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/model/parallel_for.hpp"

namespace rigdesign::metrics {
namespace {

// Whether two sorted interval lists share a point (touching ends count: a planar scanner's
// wedge is thin, and one point seen by both is enough).
bool intervals_meet(const geometry::IntervalSet& first, const geometry::IntervalSet& second) {
  const auto& x = first.intervals();
  const auto& y = second.intervals();
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < x.size() && j < y.size()) {
    if (std::max(x[i].first, y[j].first) <= std::min(x[i].second, y[j].second)) return true;
    (x[i].second < y[j].second) ? ++i : ++j;
  }
  return false;
}

// The floor point of the column is seen (an interval starting at z = 0).
bool sees_floor(const geometry::IntervalSet& column) {
  return !column.empty() && column.intervals().front().first <= 1e-9;
}

}  // namespace

double covisibility_distance(const model::Rig& rig) {
  double distance = rig.distance_of_interest;
  for (const model::Mount& mount : rig.mounts)
    distance = std::max(distance, rig.distance_for(mount));
  return distance;
}

Covisibility covisibility(const model::Rig& rig, const model::SensorLibrary& library,
                          double distance, const CovisibilitySettings& settings) {
  const geometry::BodyOccluder body(rig.body);
  std::vector<detail::PlacedMount> mounts;
  for (const model::Mount& mount : rig.mounts)
    mounts.push_back(detail::place_mount(rig, mount, library, body));
  CoverageSettings sampling;
  sampling.step = settings.step;
  const std::vector<double> thetas = detail::sampled_azimuths(sampling);
  const double dtheta = 2 * std::numbers::pi / static_cast<double>(thetas.size());
  const std::size_t n = mounts.size();
  // Per azimuth, per pair (a * n + b): its areas there.
  std::vector<std::vector<PairOverlap>> per_angle(thetas.size(), std::vector<PairOverlap>(n * n));
  const int threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  model::parallel_for(thetas.size(), threads, [&](std::size_t k) {
    const geometry::SectionFrame frame = geometry::section_frame(body, thetas[k], distance);
    if (frame.width() <= 0) return;
    const int steps = std::max(1, static_cast<int>(std::ceil(frame.width() / settings.radial)));
    const double drho = frame.width() / steps;
    std::vector<bool> reaches(n);
    for (std::size_t m = 0; m < n; ++m) reaches[m] = mounts[m].fov.may_reach_azimuth(thetas[k]);
    std::vector<geometry::IntervalSet> columns(n);
    for (int i = 0; i < steps; ++i) {
      const double rho = frame.r + (i + 0.5) * drho;
      for (std::size_t m = 0; m < n; ++m)
        columns[m] = reaches[m] ? geometry::column_coverage(mounts[m].fov, frame, rho)
                                : geometry::IntervalSet{};
      const double cell = rho * dtheta * drho;
      for (std::size_t a = 0; a < n; ++a) {
        if (columns[a].empty()) continue;
        for (std::size_t b = a + 1; b < n; ++b) {
          if (columns[b].empty()) continue;
          PairOverlap& shared = per_angle[k][a * n + b];
          shared.column_area += cell;
          if (!intervals_meet(columns[a], columns[b])) continue;
          shared.area += cell;
          if (sees_floor(columns[a]) && sees_floor(columns[b])) shared.floor_area += cell;
        }
      }
    }
  });
  Covisibility result;
  result.distance = distance;
  result.height = rig.body.area_top();
  for (const model::Mount& mount : rig.mounts) result.mount_ids.push_back(mount.id);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      PairOverlap pair;
      pair.a = a;
      pair.b = b;
      for (const std::vector<PairOverlap>& angle : per_angle) {
        pair.column_area += angle[a * n + b].column_area;
        pair.area += angle[a * n + b].area;
        pair.floor_area += angle[a * n + b].floor_area;
      }
      result.pairs.push_back(pair);
    }
  }
  return result;
}

}  // namespace rigdesign::metrics
