// The occupancy module's only CGAL translation unit (convex_hull_3 is header-heavy).
#include "rigdesign/occupancy/occupancy_hull_region.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/convex_hull_3.h>

#include <vector>

namespace rigdesign::occupancy {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

model::Vec3 vec(const Kernel::Point_3& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

}  // namespace

HullRegion::HullRegion(std::span<const model::Vec3> points) {
  if (points.empty()) return;
  empty_ = false;
  for (const model::Vec3& p : points) box_.extend(p);
  if (points.size() < 4) return;
  std::vector<Kernel::Point_3> input;
  input.reserve(points.size());
  for (const model::Vec3& p : points) input.emplace_back(p.x(), p.y(), p.z());
  Mesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  // Coplanar or collinear input gives an open polygon or less: no volume, keep the box.
  if (hull.number_of_faces() < 4 || !CGAL::is_closed(hull)) return;
  for (const Mesh::Face_index face : hull.faces()) {
    std::vector<model::Vec3> corners;
    for (const Mesh::Vertex_index v : hull.vertices_around_face(hull.halfedge(face)))
      corners.push_back(vec(hull.point(v)));
    if (corners.size() < 3) continue;
    // CGAL orients the hull's faces counter-clockwise seen from outside: the normal points out.
    const model::Vec3 normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    const double length = normal.norm();
    if (!(length > 0.0)) continue;
    const model::Vec3 unit = normal / length;
    planes_.push_back({unit, unit.dot(corners[0])});
  }
}

bool HullRegion::contains(const model::Vec3& p, double grow) const {
  if (empty_) return false;
  if (planes_.empty()) {
    Eigen::AlignedBox3d grown = box_;
    grown.min().array() -= grow;
    grown.max().array() += grow;
    return grown.contains(p);
  }
  for (const Plane& plane : planes_)
    if (plane.normal.dot(p) > plane.offset + grow) return false;
  return true;
}

}  // namespace rigdesign::occupancy
