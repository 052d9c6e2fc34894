#pragma once
/// Floor removal (paper 1, section 3) and paper 2's negative obstacles, on clouds in the
/// robot frame (floor at z = 0, z up). Parameters: rigdesign/model/filter_params.hpp.
#include "rigdesign/filters/pass_through.hpp"
#include "rigdesign/filters/ransac_plane.hpp"
#include "rigdesign/filters/voxel_grid.hpp"

namespace rigdesign::filters {

model::PointCloud remove_floor_1(const model::PointCloud& cloud,
                                 const model::FloorRemoval1Params& params = {});
model::PointCloud remove_floor_2(const model::PointCloud& cloud,
                                 const model::FloorRemoval2Params& params = {});
/// Paper 2's negative obstacles: every point below `params.below` mirrored to (x, y, -z), in
/// input order with the points kept as they are; then one virtual point per mirrored point at
/// `params.virtual_height` where the ray from the cloud's origin to it crosses z = 0, appended
/// after all of them in the same order (the scenario runner reads them from the end).
model::PointCloud mark_negative_obstacles(const model::PointCloud& cloud,
                                          const model::NegativeObstacleParams& params = {});

}  // namespace rigdesign::filters
