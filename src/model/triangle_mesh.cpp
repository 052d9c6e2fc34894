#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::model {

void TriangleMesh::append(const TriangleMesh& other, const Pose3& T) {
  const int base = static_cast<int>(vertices.size());
  for (const Vec3& vertex : other.vertices) vertices.push_back(T * vertex);
  for (const auto& triangle : other.triangles) {
    triangles.push_back({triangle[0] + base, triangle[1] + base, triangle[2] + base});
  }
}

}  // namespace rigdesign::model
