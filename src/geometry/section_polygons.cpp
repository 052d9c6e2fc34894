#include "rigdesign/geometry/section_polygons.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "rigdesign/model/polygon_area.hpp"

namespace rigdesign::geometry {
namespace {

struct Column {
  double rho;
  IntervalSet covered;
};

bool same_topology(const IntervalSet& a, const IntervalSet& b) {
  return a.intervals().size() == b.intervals().size();
}

// Largest distance between the intervals at `middle` and the straight interpolation of the
// intervals at the two ends (same topology assumed).
double chord_error(const IntervalSet& left, const IntervalSet& right, const IntervalSet& middle) {
  double worst = 0.0;
  for (std::size_t i = 0; i < middle.intervals().size(); ++i) {
    const auto& [l0, l1] = left.intervals()[i];
    const auto& [r0, r1] = right.intervals()[i];
    const auto& [m0, m1] = middle.intervals()[i];
    worst = std::max({worst, std::abs(m0 - 0.5 * (l0 + r0)), std::abs(m1 - 0.5 * (l1 + r1))});
  }
  return worst;
}

class ColumnSampler {
 public:
  ColumnSampler(const MountedFov& fov, const SectionFrame& frame, const TessellationSettings& s)
      : fov_(fov), frame_(frame), settings_(s) {}

  std::vector<Column> sample() {
    const int steps =
        std::max(1, static_cast<int>(std::ceil(frame_.width() / settings_.initial_step)));
    std::vector<Column> columns;
    Column left = at(frame_.r);
    columns.push_back(left);
    for (int i = 1; i <= steps; ++i) {
      const Column right = at(frame_.r + frame_.width() * i / steps);
      refine(left, right, columns);
      columns.push_back(right);
      left = right;
    }
    return columns;
  }

 private:
  Column at(double rho) const { return {rho, column_coverage(fov_, frame_, rho)}; }

  // Inserts the columns strictly between `left` and `right` that the tolerance needs.
  void refine(const Column& left, const Column& right, std::vector<Column>& out) const {
    if (right.rho - left.rho <= settings_.min_gap) return;
    const Column middle = at(0.5 * (left.rho + right.rho));
    const bool smooth =
        same_topology(left.covered, right.covered) && same_topology(left.covered, middle.covered) &&
        chord_error(left.covered, right.covered, middle.covered) <= settings_.tolerance;
    if (smooth) return;
    refine(left, middle, out);
    out.push_back(middle);
    refine(middle, right, out);
  }

  const MountedFov& fov_;
  const SectionFrame& frame_;
  const TessellationSettings& settings_;
};

void push_distinct(Polygon2& polygon, const model::Vec2& vertex) {
  if (polygon.empty() || (polygon.back() - vertex).norm() > 1e-12) polygon.push_back(vertex);
}

// A run of columns with the same number of intervals becomes one strip polygon per interval:
// the lower boundary left to right, then the upper boundary right to left.
void close_strips(const std::vector<Column>& columns, std::size_t first, std::size_t last,
                  std::vector<Polygon2>& polygons) {
  if (last <= first) return;  // a single column has no area
  const std::size_t strips = columns[first].covered.intervals().size();
  for (std::size_t k = 0; k < strips; ++k) {
    Polygon2 polygon;
    for (std::size_t c = first; c <= last; ++c) {
      push_distinct(polygon, model::Vec2(columns[c].rho, columns[c].covered.intervals()[k].first));
    }
    for (std::size_t c = last + 1; c-- > first;) {
      push_distinct(polygon, model::Vec2(columns[c].rho, columns[c].covered.intervals()[k].second));
    }
    if (polygon.size() > 2 && (polygon.front() - polygon.back()).norm() <= 1e-12)
      polygon.pop_back();
    if (polygon.size() >= 3 && model::signed_area(polygon) > 1e-14)
      polygons.push_back(std::move(polygon));
  }
}

}  // namespace

std::vector<Polygon2> section_polygons(const MountedFov& fov, const SectionFrame& frame,
                                       const TessellationSettings& settings) {
  if (!fov.may_reach_azimuth(frame.theta)) return {};
  const std::vector<Column> columns = ColumnSampler(fov, frame, settings).sample();
  std::vector<Polygon2> polygons;
  std::size_t run_start = 0;
  for (std::size_t c = 1; c < columns.size(); ++c) {
    if (!same_topology(columns[c].covered, columns[run_start].covered)) {
      close_strips(columns, run_start, c - 1, polygons);
      run_start = c;
    }
  }
  close_strips(columns, run_start, columns.size() - 1, polygons);
  return polygons;
}

}  // namespace rigdesign::geometry
