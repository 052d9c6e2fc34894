#include "rigdesign/model/polygon_checks.hpp"

#include <cmath>

#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/polygon_area.hpp"

namespace rigdesign::model {
namespace {

// Twice the signed area of the triangle a b c: > 0 when c lies left of a -> b.
double turn(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Whether the closed segments p0 p1 and q0 q1 share a point (touching counts).
bool segments_meet(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double d1 = turn(q0, q1, p0);
  const double d2 = turn(q0, q1, p1);
  const double d3 = turn(p0, p1, q0);
  const double d4 = turn(p0, p1, q1);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  // Collinear cases: an end lies on the other segment.
  const auto on_segment = [](const Vec2& a, const Vec2& b, const Vec2& c) {
    return c.x() >= std::min(a.x(), b.x()) && c.x() <= std::max(a.x(), b.x()) &&
           c.y() >= std::min(a.y(), b.y()) && c.y() <= std::max(a.y(), b.y());
  };
  return (d1 == 0 && on_segment(q0, q1, p0)) || (d2 == 0 && on_segment(q0, q1, p1)) ||
         (d3 == 0 && on_segment(p0, p1, q0)) || (d4 == 0 && on_segment(p0, p1, q1));
}

std::string edge_name(std::size_t i, std::size_t n) {
  return std::to_string(i) + "-" + std::to_string((i + 1) % n);
}

}  // namespace

std::optional<std::string> polygon_problem(const std::vector<Vec2>& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return "has " + std::to_string(n) + " corners, fewer than a polygon's 3";
  if (n > kMaxPolygonCorners)
    return "has " + std::to_string(n) + " corners, more than " + std::to_string(kMaxPolygonCorners);
  for (std::size_t i = 0; i < n; ++i) {
    if (!polygon[i].allFinite() || polygon[i].cwiseAbs().maxCoeff() > kMaxCoordinate)
      return "has corner " + std::to_string(i) + " beyond +-1e8 m";
  }
  // Edges that are not neighbours must not meet; neighbours meet only at their shared corner.
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing corner
      if (segments_meet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n]))
        return "crosses itself: edge " + edge_name(i, n) + " meets edge " + edge_name(j, n);
    }
  }
  // After the crossing test: a crossing polygon's signed area (a bow tie's 0) means nothing.
  if (!(std::abs(signed_area(polygon)) > 1e-9)) return "encloses no area";
  return std::nullopt;
}

}  // namespace rigdesign::model
