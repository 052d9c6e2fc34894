#include "rigdesign/occupancy/occupancy_ground_truth.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::occupancy {
namespace {

// Samples per voxel side along a triangle's edges: four keeps the sampling gap at a quarter
// voxel, well under the spacing of the sensors' end points at the cell's distances.
constexpr double kSamplesPerVoxel = 4.0;

}  // namespace

costmap::VoxelKey VoxelLattice::key_at(const model::Vec3& p_world) const {
  return {static_cast<int>(std::floor(p_world.x() / resolution)),
          static_cast<int>(std::floor(p_world.y() / resolution)),
          static_cast<int>(std::floor((p_world.z() - z_min) / z_resolution))};
}

std::vector<costmap::VoxelKey> voxelise_surface(const model::TriangleMesh& mesh,
                                                const VoxelLattice& lattice, double z_low) {
  const double step = std::min(lattice.resolution, lattice.z_resolution) / kSamplesPerVoxel;
  std::vector<costmap::VoxelKey> keys;
  for (const auto& triangle : mesh.triangles) {
    const model::Vec3& a = mesh.vertices[static_cast<std::size_t>(triangle[0])];
    const model::Vec3& b = mesh.vertices[static_cast<std::size_t>(triangle[1])];
    const model::Vec3& c = mesh.vertices[static_cast<std::size_t>(triangle[2])];
    const double longest = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
    // n divisions per edge: neighbouring samples lie at most longest / n <= step apart.
    const int n = std::max(1, static_cast<int>(std::ceil(longest / step)));
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const model::Vec3 p =
            a + (b - a) * (static_cast<double>(i) / n) + (c - a) * (static_cast<double>(j) / n);
        if (p.z() < z_low || p.z() >= lattice.z_max) continue;
        keys.push_back(lattice.key_at(p));
      }
    }
  }
  costmap::sort_unique(keys);
  return keys;
}

std::vector<std::uint8_t> column_mask(std::span<const costmap::VoxelKey> keys,
                                      const costmap::GridWindow& window) {
  std::vector<std::uint8_t> mask(window.size(), 0);
  for (const costmap::VoxelKey& key : keys) {
    const int x = key.x - window.origin_cell.x();
    const int y = key.y - window.origin_cell.y();
    if (window.contains(x, y)) mask[window.index(x, y)] = 1;
  }
  return mask;
}

std::vector<std::uint8_t> dilate_mask(std::span<const std::uint8_t> mask,
                                      const costmap::GridWindow& window, double radius) {
  std::vector<std::uint8_t> dilated(mask.begin(), mask.end());
  const int reach = static_cast<int>(std::floor(radius / window.resolution));
  const double limit = (radius / window.resolution) * (radius / window.resolution);
  for (int y = 0; y < window.height; ++y) {
    for (int x = 0; x < window.width; ++x) {
      if (mask[window.index(x, y)] == 0) continue;
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          if (dx * dx + dy * dy > limit || !window.contains(x + dx, y + dy)) continue;
          dilated[window.index(x + dx, y + dy)] = 1;
        }
      }
    }
  }
  return dilated;
}

}  // namespace rigdesign::occupancy
