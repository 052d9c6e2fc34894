#pragma once
/// The 2D obstacle layer (nav2 ObstacleLayer; DESIGN.md section 7): per update, clear the
/// cells every clearing ray crosses in 2D, then mark the cells of the end points of every
/// marking source. Only points within the source's height band take part, as in nav2, so a
/// ray over a low obstacle clears it: the 2D layer's known blind spot that the voxel layer and
/// the Hit Layer address.
#include <span>

#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::costmap {

struct ObstacleLayerParams {
  /// nav2's `track_unknown_space`: cells start (and enter the window) unknown rather than free.
  bool track_unknown_space = false;
};

class ObstacleLayer {
 public:
  ObstacleLayer() = default;
  explicit ObstacleLayer(const GridWindow& window, const ObstacleLayerParams& params = {});

  /// Clear then mark (see the file comment); ranges as in VoxelLayer::update, measured in 3D
  /// from the sensor origin. Rays are walked cell by cell (Amanatides-Woo, every cell the
  /// segment crosses) and clipped to the window. Deterministic.
  void update(std::span<const CloudObservation> observations);

  void recentre(const model::Vec2& centre_world) { grid_.recentre(centre_world); }
  void move_origin(const Eigen::Vector2i& origin_cell) { grid_.move_origin(origin_cell); }

  /// cost::kLethal, cost::kFree or cost::kUnknown per cell.
  const CostGrid& grid() const { return grid_; }
  CostGrid& grid() { return grid_; }

 private:
  CostGrid grid_;
};

}  // namespace rigdesign::costmap
