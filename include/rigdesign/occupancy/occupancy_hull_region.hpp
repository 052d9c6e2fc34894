#pragma once
/// Where paper 3 counts false positives (section III-C, as ../shared/DESIGN.md section 9 states
/// it): voxels a framework shows occupied, not in the truth, inside the convex hull of the
/// actor's points. CGAL stays inside the implementation file.
#include <span>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::occupancy {

class HullRegion {
 public:
  /// The 3D convex hull of `points`; with fewer than four points, or all of them in one plane
  /// (a hull without volume), the points' axis-aligned bounding box stands in for it.
  explicit HullRegion(std::span<const model::Vec3> points);

  /// Whether `p` lies inside the region grown by `grow` [m] (every face plane moved out by it,
  /// or the box grown by it). A voxel is counted when its centre is inside the region grown
  /// by half a voxel side: the voxels the hull passes through.
  bool contains(const model::Vec3& p, double grow) const;

  bool empty() const { return empty_; }
  bool is_box() const { return planes_.empty(); }

 private:
  struct Plane {
    model::Vec3 normal;  ///< unit, outward
    double offset;       ///< normal . x <= offset inside
  };
  std::vector<Plane> planes_;
  Eigen::AlignedBox3d box_;
  bool empty_ = true;
};

}  // namespace rigdesign::occupancy
