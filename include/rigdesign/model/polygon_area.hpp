#pragma once
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// Signed area of a simple polygon by the shoelace formula [m^2]: positive when its
/// vertices run counter-clockwise.
double signed_area(const std::vector<Vec2>& polygon);

/// Whether `p` lies inside the simple polygon `polygon` (either winding), by the even-odd
/// rule; a point exactly on an edge may fall either way.
bool inside_polygon(const std::vector<Vec2>& polygon, const Vec2& p);

/// A footprint's two radii about the origin, as nav2 derives them from its polygon: the
/// circumscribed one (the farthest corner) and the inscribed one (the nearest edge's line,
/// never more than the circumscribed one; zero-length edges are skipped) [m].
struct PolygonRadii {
  double circumscribed = 0.0;
  double inscribed = 0.0;
};
PolygonRadii polygon_radii(const std::vector<Vec2>& polygon);

}  // namespace rigdesign::model
