#include "rigdesign/costmap/rolling_voxel_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::costmap {
namespace {

// A band that is a whole number of layers up to rounding (2.0 / 0.1 = 19.999...) must not
// gain a layer.
constexpr double kLayerRounding = 1e-9;

constexpr auto kUnknown = static_cast<std::uint8_t>(VoxelState::unknown);

}  // namespace

RollingVoxelGrid::RollingVoxelGrid(const GridWindow& window, double z_min, double z_max,
                                   double z_resolution)
    : window_(window),
      layers_(std::max(
          1, static_cast<int>(std::ceil((z_max - z_min) / z_resolution - kLayerRounding)))),
      z_min_(z_min),
      z_resolution_(z_resolution),
      voxels_(window.size() * static_cast<std::size_t>(layers_), kUnknown) {}

void RollingVoxelGrid::move_origin(const Eigen::Vector2i& origin_cell) {
  detail::shift_blocks(voxels_, scratch_, window_.width, window_.height,
                       static_cast<std::size_t>(layers_),
                       Eigen::Vector2i(origin_cell - window_.origin_cell), kUnknown);
  window_.origin_cell = origin_cell;
}

void RollingVoxelGrid::reset() {
  std::fill(voxels_.begin(), voxels_.end(), kUnknown);
}

VoxelKey RollingVoxelGrid::key_at(const model::Vec3& p_world) const {
  const Eigen::Vector2i cell = window_.lattice_of(p_world.head<2>());
  return {cell.x(), cell.y(), static_cast<int>(std::floor((p_world.z() - z_min_) / z_resolution_))};
}

std::vector<VoxelKey> RollingVoxelGrid::keys_in_state(VoxelState state) const {
  const auto wanted = static_cast<std::uint8_t>(state);
  std::vector<VoxelKey> keys;
  for (int y = 0; y < window_.height; ++y) {
    for (int x = 0; x < window_.width; ++x) {
      for (int z = 0; z < layers_; ++z) {
        if (voxels_[index(x, y, z)] == wanted) keys.push_back(key_of(x, y, z));
      }
    }
  }
  // The scan runs y-major; VoxelKey orders x first.
  std::sort(keys.begin(), keys.end());
  return keys;
}

void sort_unique(std::vector<VoxelKey>& keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

}  // namespace rigdesign::costmap
