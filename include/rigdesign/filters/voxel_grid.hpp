#pragma once
/// Voxel Grid: one point per occupied voxel, the centroid of its points (paper 1, section 3;
/// V1 = 3 cm). Same semantics as PCL's VoxelGrid, so output sizes compare one to one.
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign {

struct VoxelGridParams {
  double leaf = 0.03;  ///< [m] voxel edge (paper 1: V1 = 3 cm); > 0
  /// [m] voxel boundaries lie at grid_offset + k * leaf on each axis. 0 is PCL's alignment,
  /// which puts the floor plane z = 0 exactly on a boundary, so sensor noise splits floor
  /// points between two voxel layers (about 16 % more voxels than a half-leaf offset gives).
  Eigen::Vector3d grid_offset = Eigen::Vector3d::Zero();
};

/// Throws InputError (field "voxel_grid.leaf") when the leaf is <= 0 or so small that a
/// voxel index along an axis would not fit in 21 bits (PCL's limit is the same idea):
/// refused, never wrapped around.
PointCloud voxel_grid(const PointCloud& cloud, const VoxelGridParams& params = {});

}  // namespace rigdesign
