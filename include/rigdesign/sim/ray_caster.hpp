#pragma once
/// First-hit ray casting against a triangle mesh with a CGAL AABB tree (DESIGN.md
/// section 6). CGAL stays inside the implementation file.
#include <memory>
#include <optional>

#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::sim {

class RayCaster {
 public:
  explicit RayCaster(const model::TriangleMesh& mesh);
  /// `mesh` over an `underlay` cast as well (kept by reference: it must outlive this one):
  /// a scene's few moving objects at one instant over its still objects' tree, built once.
  RayCaster(const model::TriangleMesh& mesh, const RayCaster& underlay);
  ~RayCaster();
  RayCaster(RayCaster&&) noexcept;
  RayCaster& operator=(RayCaster&&) noexcept;

  /// Distance [m] from `origin` along the unit `direction` to the first triangle hit, if any.
  std::optional<double> first_hit(const model::Vec3& origin, const model::Vec3& direction) const;

 private:
  std::optional<double> own_first_hit(const model::Vec3& origin,
                                      const model::Vec3& direction) const;
  struct Tree;
  std::unique_ptr<Tree> tree_;
  const RayCaster* underlay_ = nullptr;
};

}  // namespace rigdesign::sim
