#pragma once
/// What the occupancy evaluation (issue 6) drives: a mapper that takes each frame's clouds and
/// shows occupied voxels on a lattice, and maybe a 2D grid a planner reads. Ours is the
/// costmap's voxel layer, with or without hit-style persistence; the peer benchmark wraps
/// OctoMap in the same interface so both see the same frames and the same scoring.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/model/point_cloud.hpp"
#include "rigdesign/occupancy/occupancy_ground_truth.hpp"

namespace rigdesign::occupancy {

class OccupancyMapper {
 public:
  virtual ~OccupancyMapper() = default;
  virtual std::string name() const = 0;
  /// The lattice the keys of occupied() lie on.
  virtual VoxelLattice lattice() const = 0;
  /// One update at `time` [s] with every sensor's cloud of the frame, in the world frame with
  /// the sensor origin set. `robot_moving` is the velocity command a persistence layer's motion
  /// condition takes (the cell's sensors never move, so the position alone says "standing").
  virtual void update(double time, std::span<const model::PointCloud> clouds_world,
                      bool robot_moving) = 0;
  /// The voxels shown occupied now.
  virtual std::vector<costmap::VoxelKey> occupied() const = 0;
  /// [bytes] the map's own storage now (its voxels, counts and grids; not the scratch space
  /// of an update): what the comparison reports as memory at the end of the run.
  virtual std::size_t memory_bytes() const = 0;
  /// The planner's grid over `window`: 1 where the robot's centre may not go (inscribed or
  /// lethal cost), 0 elsewhere; empty when the mapper feeds no planner.
  virtual std::vector<std::uint8_t> blocked_cells(const costmap::GridWindow& window) const;
};

/// Our mapper: paper 2's voxel layer in the layered costmap (voxel layer, Hit Layer,
/// inflation), static at the cell frame's origin.
struct VoxelMapperParams {
  double voxel = 0.1;  ///< [m] voxel side (cubic voxels, so OctoMap's lattice matches)
  /// Hit-style persistence: paper 1's eqs. (8), (9) per voxel (the voxels shown are those with
  /// a positive count) and the Hit Layer on the 2D grid. Off: the voxel layer's own states.
  bool persistence = false;
  costmap::HitLayerParams hit;        ///< paper 1's values by default
  double window_size = 6.0;           ///< [m] square window centred on the cell (its 6 m floor)
  double z_max = 2.0;                 ///< [m] top of the voxel band (nav2's max_obstacle_height)
  double robot_radius = 0.3;          ///< [m] inscribed radius of the robot the planner guards
  costmap::ObservationSource source;  ///< per-sensor flags and ranges (same for every sensor)
};

/// "none", or "hit H/M" with the Hit Layer's counts: how reports name a persistence setting.
std::string persistence_label(const VoxelMapperParams& params);

/// Throws InputError (at `where`, fields prefixed "voxel", "hit.") through
/// check_costmap_params when the parameters cannot make a costmap.
std::unique_ptr<OccupancyMapper> make_voxel_mapper(const VoxelMapperParams& params,
                                                   const model::SourceLocation& where);

/// The square window of `size` [m] centred on the world origin at `resolution` [m], as the
/// costmap builds its own (sides lround(size / resolution) cells).
costmap::GridWindow centred_window(double size, double resolution);

}  // namespace rigdesign::occupancy
