#pragma once
/// Floor removal (paper 1, section 3) and paper 2's negative obstacles, on clouds in the
/// robot frame (floor at z = 0, z up). Parameters: rigdesign/model/filter_params.hpp.
#include "rigdesign/filters/pass_through.hpp"
#include "rigdesign/filters/ransac_plane.hpp"
#include "rigdesign/filters/voxel_grid.hpp"

namespace rigdesign {

PointCloud remove_floor_1(const PointCloud& cloud, const FloorRemoval1Params& params = {});
PointCloud remove_floor_2(const PointCloud& cloud, const FloorRemoval2Params& params = {});
PointCloud mark_negative_obstacles(const PointCloud& cloud,
                                   const NegativeObstacleParams& params = {});

}  // namespace rigdesign
