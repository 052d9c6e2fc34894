#pragma once
/// Ground truth for paper 3's occupancy evaluation (issue 6): the voxels a mesh's surface
/// occupies on the voxel layer's lattice, their column projection onto a 2D window, and that
/// projection dilated by the robot's radius (what the planner's master grid should block).
///
/// Surface, not solid volume: every mapper scored here (ours, OctoMap) marks the voxels that
/// hold measured end points, and a range sensor only ever measures a surface. Interior voxels
/// of a solid truth could never be marked by any of them, so they would lower every recall by
/// the same geometric share (about a third of the person's voxels at 5 cm) and say nothing
/// about the mapper. docs/occupancy.md discusses it.
#include <cstdint>
#include <span>
#include <vector>

#include "rigdesign/costmap/rolling_grid.hpp"
#include "rigdesign/costmap/rolling_voxel_grid.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::occupancy {

/// The voxel layer's world-fixed lattice (RollingVoxelGrid::key_at): x = floor(x / r),
/// y = floor(y / r), z = floor((z - z_min) / r_z).
struct VoxelLattice {
  double resolution = 0.1;    ///< [m] voxel side in x and y
  double z_resolution = 0.1;  ///< [m] voxel height
  double z_min = 0.0;         ///< [m] world z of layer 0's bottom
  double z_max = 2.0;         ///< [m] top of the band; voxels holding z >= z_max are left out

  costmap::VoxelKey key_at(const model::Vec3& p_world) const;
};

/// Every lattice voxel that holds a point of the mesh's surface at a height in [z_low, z_max),
/// ascending and unique. The surface is sampled on a barycentric grid with steps of at most a
/// quarter of the smaller voxel side, so a voxel the surface only clips by less than that can
/// be missed (a sliver no range sensor would hit either). Deterministic.
std::vector<costmap::VoxelKey> voxelise_surface(const model::TriangleMesh& mesh,
                                                const VoxelLattice& lattice, double z_low);

/// 1 for every cell of `window` under some key's column, else 0 (row-major, window.index).
std::vector<std::uint8_t> column_mask(std::span<const costmap::VoxelKey> keys,
                                      const costmap::GridWindow& window);

/// 1 for every cell whose centre lies within `radius` [m] of an occupied cell's centre
/// (the occupied cells included); cells outside the window do not contribute.
std::vector<std::uint8_t> dilate_mask(std::span<const std::uint8_t> mask,
                                      const costmap::GridWindow& window, double radius);

}  // namespace rigdesign::occupancy
