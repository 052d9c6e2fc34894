#include "rigdesign/model/polygon_area.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::model {

double signed_area(const std::vector<Vec2>& polygon) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return twice_area / 2;
}

bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

PolygonRadii polygon_radii(const std::vector<Vec2>& polygon) {
  PolygonRadii radii;
  for (const Vec2& corner : polygon)
    radii.circumscribed = std::max(radii.circumscribed, corner.norm());
  radii.inscribed = radii.circumscribed;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2 edge = polygon[(i + 1) % polygon.size()] - a;
    const double length = edge.norm();
    if (length > 0.0) {
      radii.inscribed =
          std::min(radii.inscribed, std::abs(edge.x() * a.y() - edge.y() * a.x()) / length);
    }
  }
  return radii;
}

}  // namespace rigdesign::model
