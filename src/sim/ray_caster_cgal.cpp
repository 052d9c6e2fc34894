// The simulator's only CGAL translation unit (AABB trees are header-heavy).
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <vector>

#include "rigdesign/sim/ray_caster.hpp"

namespace rigdesign::sim {
namespace {

// Floating-point construction is enough here: a hit point off by 1e-12 m is far below
// any sensor's noise, and the tree only needs robust predicates for traversal.
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const model::Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace

struct RayCaster::Tree {
  std::vector<Triangle> triangles;
  sim::Tree tree;
};

RayCaster::RayCaster(const model::TriangleMesh& mesh) : tree_(std::make_unique<Tree>()) {
  for (const auto& t : mesh.triangles) {
    const Triangle triangle(point(mesh.vertices[t[0]]), point(mesh.vertices[t[1]]),
                            point(mesh.vertices[t[2]]));
    if (!triangle.is_degenerate()) tree_->triangles.push_back(triangle);
  }
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
}

RayCaster::RayCaster(const model::TriangleMesh& mesh, const RayCaster& underlay) : RayCaster(mesh) {
  underlay_ = &underlay;
}

RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

std::optional<double> RayCaster::first_hit(const model::Vec3& origin,
                                           const model::Vec3& direction) const {
  const std::optional<double> own = own_first_hit(origin, direction);
  if (!underlay_) return own;
  const std::optional<double> under = underlay_->first_hit(origin, direction);
  if (!own) return under;
  if (!under) return own;
  return std::min(*own, *under);
}

std::optional<double> RayCaster::own_first_hit(const model::Vec3& origin,
                                               const model::Vec3& direction) const {
  if (tree_->triangles.empty()) return std::nullopt;
  const Kernel::Ray_3 ray(point(origin),
                          Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
  const auto hit = tree_->tree.first_intersection(ray);
  if (!hit) return std::nullopt;
  if (const Kernel::Point_3* p = boost::get<Kernel::Point_3>(&hit->first)) {
    return (model::Vec3(p->x(), p->y(), p->z()) - origin).norm();
  }
  if (const Kernel::Segment_3* s =
          boost::get<Kernel::Segment_3>(&hit->first)) {  // ray in the triangle's plane
    const model::Vec3 a(s->source().x(), s->source().y(), s->source().z());
    const model::Vec3 b(s->target().x(), s->target().y(), s->target().z());
    return std::min((a - origin).norm(), (b - origin).norm());
  }
  return std::nullopt;
}

}  // namespace rigdesign::sim
