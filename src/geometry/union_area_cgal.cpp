// The only translation unit that includes CGAL's Boolean set operations (they take ~30 s to
// compile), so rebuilds elsewhere stay fast.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include "rigdesign/geometry/section_polygons.hpp"

namespace rigdesign::geometry {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Kernel>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using CgalPolygonSet = CGAL::Polygon_set_2<Kernel>;

CgalPolygon to_cgal(const Polygon2& polygon) {
  CgalPolygon result;
  for (const model::Vec2& vertex : polygon)
    result.push_back(Kernel::Point_2(vertex.x(), vertex.y()));
  if (result.is_clockwise_oriented()) result.reverse_orientation();
  return result;
}

}  // namespace

double union_area(const std::vector<std::vector<Polygon2>>& per_sensor) {
  std::vector<CgalPolygon> polygons;
  for (const auto& sensor : per_sensor) {
    for (const Polygon2& polygon : sensor) polygons.push_back(to_cgal(polygon));
  }
  if (polygons.empty()) return 0.0;
  CgalPolygonSet united;
  united.join(polygons.begin(), polygons.end());
  std::vector<CgalPolygonWithHoles> pieces;
  united.polygons_with_holes(std::back_inserter(pieces));
  Kernel::FT area = 0;
  for (const CgalPolygonWithHoles& piece : pieces) {
    area += piece.outer_boundary().area();
    for (auto hole = piece.holes_begin(); hole != piece.holes_end(); ++hole) area += hole->area();
  }
  return CGAL::to_double(area);
}

}  // namespace rigdesign::geometry
