#pragma once
/// The parameter sweep of issue 6 (like paper 3's Tables 2-4, which swept OctoMap's voxel
/// length and hit/miss probabilities): voxel lengths x persistence settings, every
/// combination one mapper, all run on the same frames.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/occupancy/occupancy_voxel_mapper.hpp"

namespace rigdesign::occupancy {

/// One persistence setting: none (the voxel layer alone), or per-voxel hit counts with these
/// `hit` and `hit_max` (paper 1's eqs. 8, 9: a voxel seen n times in a row stays about
/// hit x n updates after the last sighting, capped at hit_max, while the robot moves).
struct PersistenceSetting {
  bool enabled = false;
  int hit = costmap::HitLayerParams{}.hit;  ///< paper 1's values by default (costmap's params)
  int hit_max = costmap::HitLayerParams{}.hit_max;
};

/// Issue 6's defaults: 0.05, 0.1, 0.15 and 0.2 m.
std::vector<double> default_sweep_voxels();
/// None; hit 1/15; hit 3/1500 (paper 1); hit 3/30 (a short memory); hit 10/1500.
std::vector<PersistenceSetting> default_sweep_persistence();

/// Every (voxel, persistence) pair, voxel-major in the given orders; `base` supplies the
/// other fields.
std::vector<VoxelMapperParams> sweep_grid(std::span<const double> voxels,
                                          std::span<const PersistenceSetting> persistence,
                                          const VoxelMapperParams& base = {});

/// One mapper per row of the grid; throws InputError (at `where`) for parameters no costmap
/// accepts.
std::vector<std::unique_ptr<OccupancyMapper>> make_sweep_mappers(
    std::span<const VoxelMapperParams> grid, const model::SourceLocation& where);

}  // namespace rigdesign::occupancy
