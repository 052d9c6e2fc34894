#pragma once
/// Paper 2's voxel layer (DESIGN.md section 7): per update, first clear every voxel on the ray
/// from the sensor origin to each point, then mark the end voxels, so a cloud can never clear
/// its own new marks; columns project to 2D as occupied if any voxel is occupied, unknown if
/// more than `unknown_threshold` voxels are unknown, else free.
#include <span>

#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/costmap/rolling_grid.hpp"
#include "rigdesign/costmap/rolling_voxel_grid.hpp"

namespace rigdesign::costmap {

struct VoxelLayerParams {
  double z_min = 0.0;          ///< [m] world z of the band's bottom
  double z_max = 2.0;          ///< [m] world z of the band's top
  double z_resolution = 0.05;  ///< [m] voxel height (x and y use the 2D window's resolution)
  /// Paper 2: a column with more than this many unknown voxels (and none occupied) projects
  /// as unknown (nav2's `unknown_threshold` plays the same role).
  int unknown_threshold = 4;
};

/// What one update did, for benchmarks and logs.
struct VoxelUpdateStats {
  std::size_t points = 0;          ///< points read
  std::size_t rays_cleared = 0;    ///< rays that cleared at least their first voxel
  std::size_t voxels_cleared = 0;  ///< voxel visits while clearing (a voxel may count twice)
  std::size_t voxels_marked = 0;   ///< end points that marked a voxel
};

class VoxelLayer {
 public:
  VoxelLayer() = default;
  /// Every voxel starts unknown. Preconditions as RollingVoxelGrid's.
  VoxelLayer(const GridWindow& window, const VoxelLayerParams& params);

  /// Clears along every ray of every observation whose source clears (from
  /// raytrace_min_range to the point, or to raytrace_max_range when the point is farther;
  /// the end voxel of a ray that reaches its point is left alone), then marks the end voxel
  /// of every point of every marking source that lies within [obstacle_min_range,
  /// obstacle_max_range] of the sensor origin and within [min_obstacle_height,
  /// max_obstacle_height] in world z. Rays are clipped to the window. Single-threaded,
  /// deterministic.
  VoxelUpdateStats update(std::span<const CloudObservation> observations);
  /// One cloud, clear then mark (the same as update with one observation).
  VoxelUpdateStats insert(const CloudObservation& observation) { return update({&observation, 1}); }

  /// Writes the column projection into `grid` (resized to this layer's window): cost::kLethal,
  /// cost::kUnknown or cost::kFree per paper 2's rule.
  void project(CostGrid& grid) const;

  void recentre(const model::Vec2& centre_world) { grid_.recentre(centre_world); }
  void move_origin(const Eigen::Vector2i& origin_cell) { grid_.move_origin(origin_cell); }

  const RollingVoxelGrid& grid() const { return grid_; }
  RollingVoxelGrid& grid() { return grid_; }
  const VoxelLayerParams& params() const { return params_; }

 private:
  VoxelLayerParams params_;
  RollingVoxelGrid grid_;
};

}  // namespace rigdesign::costmap
