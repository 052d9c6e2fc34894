#include "rigdesign/geometry/footprint_hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <iterator>

#include "rigdesign/geometry/body_mesh.hpp"

namespace rigdesign::geometry {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

}  // namespace

std::vector<model::Vec2> footprint_hull(const model::RobotBody& body) {
  // The body's closed mesh holds every corner of its projection (cylinders as the polygons
  // the rest of rigdesign draws them with).
  const model::TriangleMesh mesh = body_mesh(body);
  std::vector<model::Vec2> corners;
  corners.reserve(mesh.vertices.size());
  for (const model::Vec3& v : mesh.vertices) corners.emplace_back(v.x(), v.y());
  return convex_hull(corners);
}

std::vector<model::Vec2> convex_hull(const std::vector<model::Vec2>& corners) {
  std::vector<Kernel::Point_2> points;
  points.reserve(corners.size());
  for (const model::Vec2& v : corners) points.emplace_back(v.x(), v.y());
  std::vector<Kernel::Point_2> hull;
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  std::vector<model::Vec2> outline;
  outline.reserve(hull.size());
  for (const Kernel::Point_2& p : hull) outline.emplace_back(p.x(), p.y());
  return outline;
}

}  // namespace rigdesign::geometry
