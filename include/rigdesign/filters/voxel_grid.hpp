#pragma once
/// Voxel Grid: one point per occupied voxel, the centroid of its points (paper 1, section 3;
/// V1 = 3 cm). Same semantics as PCL's VoxelGrid, so output sizes compare one to one.
#include "rigdesign/model/filter_params.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

/// Throws InputError (field "voxel_grid.leaf") when the leaf is <= 0 or so small that a
/// voxel index along an axis would not fit in 21 bits (PCL's limit is the same idea):
/// refused, never wrapped around.
model::PointCloud voxel_grid(const model::PointCloud& cloud,
                             const model::VoxelGridParams& params = {});

}  // namespace rigdesign::filters
