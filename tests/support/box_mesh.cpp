#include "support/box_mesh.hpp"

namespace rigdesign::test {

model::TriangleMesh box_mesh(const model::Vec3& low, const model::Vec3& high) {
  model::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {  // corner i: bit 0 picks x, bit 1 y, bit 2 z
    mesh.vertices.emplace_back(i & 1 ? high.x() : low.x(), i & 2 ? high.y() : low.y(),
                               i & 4 ? high.z() : low.z());
  }
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

double surface_area(const model::TriangleMesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const model::Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const model::Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const model::Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

}  // namespace rigdesign::test
