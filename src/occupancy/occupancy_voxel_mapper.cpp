// Our side of the occupancy evaluation: the layered costmap with the voxel layer, and the
// per-voxel hit counts that give the voxel set "hit-style persistence".
#include "rigdesign/occupancy/occupancy_voxel_mapper.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::occupancy {
namespace {

costmap::CostmapParams costmap_params_of(const VoxelMapperParams& params) {
  costmap::CostmapParams costmap;
  costmap.resolution = params.voxel;
  costmap.size_x = costmap.size_y = params.window_size;
  costmap.robot_radius = params.robot_radius;
  costmap.layer = costmap::ObstacleLayerKind::voxel;
  costmap.voxel.z_min = 0.0;
  costmap.voxel.z_max = params.z_max;
  costmap.voxel.z_resolution = params.voxel;
  costmap.use_hit_layer = params.persistence;
  costmap.hit = params.hit;
  // The planner's forbidden zone is the robot's own radius around every obstacle.
  costmap.inflation.inscribed_radius = params.robot_radius;
  costmap.inflation.inflation_radius =
      std::max(costmap.inflation.inflation_radius, params.robot_radius);
  return costmap;
}

class VoxelMapper final : public OccupancyMapper {
 public:
  VoxelMapper(const VoxelMapperParams& params, const model::SourceLocation& where)
      : params_(params), costmap_(costmap_params_of(params), where) {
    if (params.persistence) counts_.assign(costmap_.voxel_layer().grid().voxels().size(), 0);
  }

  std::string name() const override {
    std::string name = "voxel " + model::format_number(params_.voxel, 3) + " m";
    if (params_.persistence) name += ", " + persistence_label(params_);
    return name;
  }

  VoxelLattice lattice() const override {
    return {params_.voxel, params_.voxel, 0.0,
            costmap_.voxel_layer().grid().z_min() +
                costmap_.voxel_layer().grid().layers() * params_.voxel};
  }

  void update(double time, std::span<const model::PointCloud> clouds_world,
              bool robot_moving) override {
    observations_.clear();
    for (const model::PointCloud& cloud : clouds_world) {
      observations_.push_back({&cloud, model::Pose3::Identity(), params_.source});
    }
    costmap_.update(time, model::Pose3::Identity(), observations_, robot_moving);
    if (params_.persistence) {
      // Paper 1, eqs. (8) and (9) per voxel, decrementing exactly when the 2D Hit Layer did.
      costmap::apply_hit_equations(costmap_.voxel_layer().grid().voxels(), counts_, params_.hit,
                                   costmap_.last_update_decremented(),
                                   static_cast<std::uint8_t>(costmap::VoxelState::occupied));
    }
  }

  std::vector<costmap::VoxelKey> occupied() const override {
    const costmap::RollingVoxelGrid& grid = costmap_.voxel_layer().grid();
    if (!params_.persistence) return grid.keys_in_state(costmap::VoxelState::occupied);
    std::vector<costmap::VoxelKey> keys;
    const costmap::GridWindow& window = grid.window();
    for (int y = 0; y < window.height; ++y) {
      for (int x = 0; x < window.width; ++x) {
        for (int z = 0; z < grid.layers(); ++z) {
          if (counts_[grid.index(x, y, z)] > 0) keys.push_back(grid.key_of(x, y, z));
        }
      }
    }
    return keys;
  }

  // The voxel grid (a byte per voxel), the hit counts and the master grid (a byte per cell).
  std::size_t memory_bytes() const override {
    return costmap_.voxel_layer().grid().voxels().size() + counts_.size() * sizeof(std::uint16_t) +
           costmap_.master().window().size();
  }

  std::vector<std::uint8_t> blocked_cells(const costmap::GridWindow& window) const override {
    const costmap::CostGrid& master = costmap_.master();
    std::vector<std::uint8_t> blocked(window.size(), 0);
    for (int y = 0; y < window.height; ++y) {
      for (int x = 0; x < window.width; ++x) {
        const Eigen::Vector2i local =
            window.origin_cell + Eigen::Vector2i(x, y) - master.window().origin_cell;
        if (!master.window().contains(local.x(), local.y())) continue;
        const std::uint8_t cost = master.at(local.x(), local.y());
        blocked[window.index(x, y)] =
            cost == costmap::cost::kLethal || cost == costmap::cost::kInscribed;
      }
    }
    return blocked;
  }

 private:
  VoxelMapperParams params_;
  costmap::Costmap costmap_;
  std::vector<std::uint16_t> counts_;
  std::vector<costmap::CloudObservation> observations_;
};

}  // namespace

std::vector<std::uint8_t> OccupancyMapper::blocked_cells(const costmap::GridWindow&) const {
  return {};
}

costmap::GridWindow centred_window(double size, double resolution) {
  costmap::GridWindow window;
  window.width = window.height = std::max(1, static_cast<int>(std::lround(size / resolution)));
  window.resolution = resolution;
  window.origin_cell = window.origin_centred_on(model::Vec2::Zero());
  return window;
}

std::unique_ptr<OccupancyMapper> make_voxel_mapper(const VoxelMapperParams& params,
                                                   const model::SourceLocation& where) {
  return std::make_unique<VoxelMapper>(params, where);
}

std::string persistence_label(const VoxelMapperParams& params) {
  return params.persistence
             ? "hit " + std::to_string(params.hit.hit) + "/" + std::to_string(params.hit.hit_max)
             : "none";
}

}  // namespace rigdesign::occupancy
