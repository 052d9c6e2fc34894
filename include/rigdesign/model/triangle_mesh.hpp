#pragma once
#include <array>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// An indexed triangle mesh, coordinates in metres.
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  ///< indices into `vertices`

  /// Appends `other`'s triangles, moved by `T` (frames: T maps other's coordinates into ours).
  void append(const TriangleMesh& other, const Pose3& T = Pose3::Identity());
};

}  // namespace rigdesign::model
