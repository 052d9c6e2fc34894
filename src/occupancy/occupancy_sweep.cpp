#include "rigdesign/occupancy/occupancy_sweep.hpp"

namespace rigdesign::occupancy {

std::vector<double> default_sweep_voxels() {
  return {0.05, 0.1, 0.15, 0.2};
}

std::vector<PersistenceSetting> default_sweep_persistence() {
  const costmap::HitLayerParams paper;
  return {{false, 0, 0},
          {true, 1, 15},
          {true, paper.hit, paper.hit_max},
          {true, paper.hit, 30},
          {true, 10, paper.hit_max}};
}

std::vector<VoxelMapperParams> sweep_grid(std::span<const double> voxels,
                                          std::span<const PersistenceSetting> persistence,
                                          const VoxelMapperParams& base) {
  std::vector<VoxelMapperParams> grid;
  for (const double voxel : voxels) {
    for (const PersistenceSetting& setting : persistence) {
      VoxelMapperParams params = base;
      params.voxel = voxel;
      params.persistence = setting.enabled;
      if (setting.enabled) {
        params.hit.hit = setting.hit;
        params.hit.hit_max = setting.hit_max;
      }
      grid.push_back(params);
    }
  }
  return grid;
}

std::vector<std::unique_ptr<OccupancyMapper>> make_sweep_mappers(
    std::span<const VoxelMapperParams> grid, const model::SourceLocation& where) {
  std::vector<std::unique_ptr<OccupancyMapper>> mappers;
  for (const VoxelMapperParams& params : grid) mappers.push_back(make_voxel_mapper(params, where));
  return mappers;
}

}  // namespace rigdesign::occupancy
