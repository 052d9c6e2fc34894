#pragma once
/// Floor removal (paper 1, section 3) and paper 2's negative obstacles, on clouds in the
/// robot frame (floor at z = 0, z up).
#include "rigdesign/filters/pass_through.hpp"
#include "rigdesign/filters/ransac_plane.hpp"
#include "rigdesign/filters/voxel_grid.hpp"

namespace rigdesign {

/// Floor removal 1: a pass-through slice around the floor, a RANSAC plane on the slice,
/// its inliers removed from the cloud.
struct FloorRemoval1Params {
  PassThroughParams slice;  ///< z in [-10, 10] cm
  RansacPlaneParams ransac;
};

/// Floor removal 2: the plane fitted on a copy voxelised at V2 = 30 cm, then every point
/// within T of it removed. The plane must be near-horizontal (RANSAC ignores hypotheses
/// tilted more than `ransac.max_tilt`, 15 degrees by default) so a wall cannot win.
struct FloorRemoval2Params {
  double coarse_leaf = 0.30;  ///< V2 [m]
  RansacPlaneParams ransac{100, 0.03, 1, 0.2617993877991494};
};

PointCloud remove_floor_1(const PointCloud& cloud, const FloorRemoval1Params& params = {});
PointCloud remove_floor_2(const PointCloud& cloud, const FloorRemoval2Params& params = {});

/// Paper 2's negative obstacles: a point below `below` (a hole or a step down) is mirrored
/// to (x, y, -z), and a virtual point is added `virtual_height` above the floor where the ray
/// from the sensor origin O to the point crosses the floor:
/// P'' = (o_x + (x - o_x) s, o_y + (y - o_y) s, virtual_height), s = o_z / (o_z - z).
struct NegativeObstacleParams {
  double below = -0.02;         ///< [m]
  double virtual_height = 0.10; ///< [m]
};

PointCloud mark_negative_obstacles(const PointCloud& cloud, const NegativeObstacleParams& params = {});

}  // namespace rigdesign
