#pragma once
/// The layered costmap (DESIGN.md section 7): a rolling window centred on the robot, an
/// obstacle layer (2D) or voxel layer (3D) fed by nav2's observation buffers (a source's
/// `observation_persistence`), the optional Hit Layer and the inflation layer, combined in
/// that order into the master grid the planner reads.
#include <cstdint>
#include <span>
#include <vector>

#include "rigdesign/costmap/hit_layer.hpp"
#include "rigdesign/costmap/inflation_layer.hpp"
#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/costmap/obstacle_layer.hpp"
#include "rigdesign/costmap/rolling_grid.hpp"
#include "rigdesign/costmap/voxel_layer.hpp"
#include "rigdesign/model/name_table.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::costmap {

enum class ObstacleLayerKind { obstacle, voxel };
inline constexpr model::NameTable<ObstacleLayerKind, 2> kObstacleLayerNames = {{
    {ObstacleLayerKind::obstacle, "obstacle"},
    {ObstacleLayerKind::voxel, "voxel"},
}};
static_assert(model::covers_in_order(kObstacleLayerNames) &&
              kObstacleLayerNames.size() == static_cast<std::size_t>(ObstacleLayerKind::voxel) + 1);

struct CostmapParams {
  double resolution = 0.05;  ///< [m] cell side (nav2 local costmap)
  double size_x = 10.0;      ///< [m] window along world x
  double size_y = 10.0;      ///< [m] window along world y
  /// [m] the footprint's circumscribed radius (RobotBody::radius); the window must hold it.
  double robot_radius = 0.1;
  ObstacleLayerKind layer = ObstacleLayerKind::voxel;
  ObstacleLayerParams obstacle;
  VoxelLayerParams voxel;
  bool use_hit_layer = true;
  HitLayerParams hit;
  InflationParams inflation;
};

/// Throws InputError listing every bad field of `params` at `where` (the file entry they came
/// from, or {"(command line)"}): resolution <= 0, a window smaller than the footprint
/// (size < 2 robot_radius), an empty z band, hit counts outside 16 bits, and so on. Field
/// names are `prefix` + the struct's member path ("resolution", "voxel.z_max", "hit.hit_max").
void check_costmap_params(const CostmapParams& params, const model::SourceLocation& where,
                          const std::string& prefix = {});

class Costmap;

/// Cells (row-major on the window) the Hit Layer keeps lethal while the obstacle grid does not
/// see them occupied now: what only its memory holds. Empty without a Hit Layer.
std::vector<std::uint8_t> remembered_cells(const Costmap& costmap);

class Costmap {
 public:
  /// Checks the parameters (check_costmap_params with `where`); the window starts centred on
  /// the world origin, every layer empty (unknown or free as the layer defines).
  explicit Costmap(const CostmapParams& params,
                   const model::SourceLocation& where = model::SourceLocation{"(command line)"});

  /// One step at `time` [s] with the robot at `T_world_robot`: centre every layer's window on
  /// the robot (the overlap kept, entering cells reset), clear then mark with every
  /// observation and every persisted one of an earlier update (nav2's ObservationBuffer: an
  /// observation stays while `time` minus its time is at most its source's
  /// observation_persistence), project the voxels, apply the Hit Layer (its motion condition from
  /// the robot's positions and `velocity_command`), copy into the master grid, mark the Hit Layer's
  /// cells lethal there, and inflate.
  void update(double time, const model::Pose3& T_world_robot,
              std::span<const CloudObservation> observations, bool velocity_command = false);

  /// Forgets every obstacle farther than `radius` [m] from `centre_world`: the obstacle
  /// layer's and the voxel layer's cells go back to their starting state, the Hit Layer's counts
  /// to 0 (nav2's clear_costmap_except_region; paper 2's deadlock recovery clears beyond 0.5 m).
  /// Clouds kept for their persistence mark again at the next update, as nav2's buffers do.
  void clear_outside(const model::Vec2& centre_world, double radius);

  const CostmapParams& params() const { return params_; }
  const GridWindow& window() const { return master_.window(); }
  /// The grid the planner reads (cost_values.hpp).
  const CostGrid& master() const { return master_; }
  /// The obstacle layer's grid, or the voxel layer's column projection: what the Hit Layer sees.
  const CostGrid& obstacle_grid() const;
  const ObstacleLayer& obstacle_layer() const { return obstacle_; }
  const VoxelLayer& voxel_layer() const { return voxel_; }
  const HitLayer& hit_layer() const { return hit_; }
  /// Whether the last update's Hit Layer decremented (false while the robot stood still).
  bool last_update_decremented() const { return decremented_; }
  /// Observations of earlier updates that still mark, by their sources' persistence.
  std::size_t persisted_observations() const { return persisted_.size(); }

 private:
  /// A cloud kept for its source's persistence, in the world frame as it was taken (nav2
  /// transforms each cloud into the global frame when it arrives).
  struct PersistedObservation {
    double time = 0.0;
    model::PointCloud cloud;
    ObservationSource source;
  };

  CostmapParams params_;
  ObstacleLayer obstacle_;
  VoxelLayer voxel_;
  CostGrid projection_;
  HitLayer hit_;
  InflationLayer inflation_;
  CostGrid master_;
  std::vector<PersistedObservation> persisted_;
  bool decremented_ = false;
};

}  // namespace rigdesign::costmap
