#include "rigdesign/costmap/voxel_layer.hpp"

#include <algorithm>
#include <cmath>

#include "cloud_marking.hpp"
#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {
namespace {

using detail::GridPoint;
using detail::GridSize;
using detail::GridStride;

constexpr auto kFreeVoxel = static_cast<std::uint8_t>(VoxelState::free);
constexpr auto kOccupiedVoxel = static_cast<std::uint8_t>(VoxelState::occupied);
constexpr auto kUnknownVoxel = static_cast<std::uint8_t>(VoxelState::unknown);

// World metres to the grid's cell units: x and y from the window's corner, z from z_min.
struct GridFrame {
  model::Vec3 corner;
  model::Vec3 inverse_size;
  GridSize<3> size;
  GridStride<3> stride;

  explicit GridFrame(const RollingVoxelGrid& grid) {
    const GridWindow& w = grid.window();
    corner = model::Vec3(w.origin().x(), w.origin().y(), grid.z_min());
    inverse_size = model::Vec3(1.0 / w.resolution, 1.0 / w.resolution, 1.0 / grid.z_resolution());
    size = GridSize<3>(w.width, w.height, grid.layers());
    // Columns are contiguous: z fastest, then x, then y.
    stride = GridStride<3>(grid.layers(), static_cast<std::ptrdiff_t>(w.width) * grid.layers(), 1);
  }
  GridPoint<3> to_grid(const model::Vec3& p_world) const {
    return (p_world - corner).cwiseProduct(inverse_size);
  }
};

// Clears the voxels from `start` towards `end` (world), the end voxel too when the ray was cut
// short of its point (range or window) and so says nothing about it.
void clear_ray(const GridFrame& frame, std::uint8_t* voxels, const model::Vec3& start,
               const model::Vec3& end, bool cut_short, VoxelUpdateStats& stats) {
  GridPoint<3> a = frame.to_grid(start);
  GridPoint<3> b = frame.to_grid(end);
  bool end_clipped = false;
  if (!detail::clip_to_grid<3>(a, b, frame.size, end_clipped)) return;
  const bool include_end = cut_short || end_clipped || !detail::inside_grid<3>(b, frame.size);
  ++stats.rays_cleared;
  std::size_t visited = 0;
  detail::walk_cells<3>(a, b, frame.size, frame.stride, include_end, [&](std::ptrdiff_t index) {
    voxels[index] = kFreeVoxel;
    ++visited;
  });
  stats.voxels_cleared += visited;
}

void clear_cloud(const GridFrame& frame, std::uint8_t* voxels, const CloudObservation& observation,
                 VoxelUpdateStats& stats) {
  const ObservationSource& source = observation.source;
  const model::Vec3 origin = observation.T_world_cloud * observation.cloud->origin.cast<double>();
  for (const model::Point3f& point : observation.cloud->points) {
    const model::Vec3 p_world = observation.T_world_cloud * point.cast<double>();
    const auto clearing = detail::clearing_ray(origin, p_world, source);
    if (!clearing) continue;
    clear_ray(frame, voxels, clearing->start, clearing->end, clearing->cut_short, stats);
  }
}

void mark_cloud(const GridFrame& frame, std::uint8_t* voxels, const CloudObservation& observation,
                VoxelUpdateStats& stats) {
  detail::for_each_marked_cell<3>(frame, observation, [&](const auto& cell) {
    voxels[cell.x() * frame.stride.x() + cell.y() * frame.stride.y() + cell.z()] = kOccupiedVoxel;
    ++stats.voxels_marked;
  });
}

}  // namespace

VoxelLayer::VoxelLayer(const GridWindow& window, const VoxelLayerParams& params)
    : params_(params), grid_(window, params.z_min, params.z_max, params.z_resolution) {}

VoxelUpdateStats VoxelLayer::update(std::span<const CloudObservation> observations) {
  VoxelUpdateStats stats;
  const GridFrame frame(grid_);
  std::uint8_t* voxels = grid_.voxels().data();
  // Every clearing before any marking: no cloud of this update can clear a fresh mark.
  for (const CloudObservation& observation : observations) {
    if (observation.cloud == nullptr) continue;
    stats.points += observation.cloud->size();
    if (observation.source.clearing) clear_cloud(frame, voxels, observation, stats);
  }
  for (const CloudObservation& observation : observations) {
    if (observation.cloud != nullptr && observation.source.marking)
      mark_cloud(frame, voxels, observation, stats);
  }
  return stats;
}

void VoxelLayer::project(CostGrid& grid) const {
  const GridWindow& window = grid_.window();
  grid.reshape(window);  // every cell is written below
  const std::uint8_t* column = grid_.voxels().data();
  const auto layers = static_cast<std::size_t>(grid_.layers());
  for (std::uint8_t& cell : grid.cells()) {
    bool occupied = false;
    int unknown = 0;
    for (std::size_t z = 0; z < layers; ++z) {
      occupied |= column[z] == kOccupiedVoxel;
      unknown += column[z] == kUnknownVoxel;
    }
    // Paper 2: occupied if any voxel is, unknown if more than the threshold are unknown.
    cell = occupied ? cost::kLethal
                    : (unknown > params_.unknown_threshold ? cost::kUnknown : cost::kFree);
    column += layers;
  }
}

}  // namespace rigdesign::costmap
