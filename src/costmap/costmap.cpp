#include "rigdesign/costmap/costmap.hpp"

#include <cmath>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {
namespace {

// Cells per side: the nearest whole number (10 m / 0.05 m = 200), at least one.
int cells_along(double size, double resolution) {
  return std::max(1, static_cast<int>(std::lround(size / resolution)));
}

GridWindow window_of(const CostmapParams& params) {
  GridWindow window;
  window.width = cells_along(params.size_x, params.resolution);
  window.height = cells_along(params.size_y, params.resolution);
  window.resolution = params.resolution;
  window.origin_cell = window.origin_centred_on(model::Vec2::Zero());
  return window;
}

// The observation's cloud in the world frame, its sensor origin with it, computed as the
// layers map points (in double) so that a kept cloud marks the cells it marked when new.
model::PointCloud world_copy(const CloudObservation& observation) {
  model::PointCloud world;
  world.points.reserve(observation.cloud->size());
  for (const model::Point3f& point : observation.cloud->points)
    world.points.push_back((observation.T_world_cloud * point.cast<double>()).cast<float>());
  world.origin =
      (observation.T_world_cloud * observation.cloud->origin.cast<double>()).cast<float>();
  return world;
}

// Checks before any layer allocates.
const CostmapParams& checked(const CostmapParams& params, const model::SourceLocation& where) {
  check_costmap_params(params, where);
  return params;
}

}  // namespace

Costmap::Costmap(const CostmapParams& params, const model::SourceLocation& where)
    : params_(checked(params, where)),
      inflation_(params.inflation),
      master_(window_of(params), cost::kUnknown) {
  const GridWindow& window = master_.window();
  if (params.layer == ObstacleLayerKind::obstacle) {
    obstacle_ = ObstacleLayer(window, params.obstacle);
  } else {
    voxel_ = VoxelLayer(window, params.voxel);
    projection_ = CostGrid(window, cost::kUnknown);
  }
  hit_ = HitLayer(window, params.hit);
}

void Costmap::clear_outside(const model::Vec2& centre_world, double radius) {
  // Every layer shares the master's window (update recentres them together).
  const GridWindow& window = master_.window();
  CostGrid& obstacles = obstacle_.grid();
  RollingVoxelGrid& voxels = voxel_.grid();
  const bool has_voxels = voxels.window().size() == window.size();
  const bool has_hits = hit_.counts().window().size() == window.size();
  for (int y = 0; y < window.height; ++y) {
    for (int x = 0; x < window.width; ++x) {
      if ((window.centre_of(x, y) - centre_world).norm() <= radius) continue;
      if (obstacles.window().size() == window.size()) obstacles.at(x, y) = obstacles.fill_value();
      if (has_voxels) {
        for (int z = 0; z < voxels.layers(); ++z) voxels.set(x, y, z, VoxelState::unknown);
      }
      if (has_hits) hit_.counts().at(x, y) = 0;
    }
  }
}

const CostGrid& Costmap::obstacle_grid() const {
  return params_.layer == ObstacleLayerKind::obstacle ? obstacle_.grid() : projection_;
}

void Costmap::update(double time, const model::Pose3& T_world_robot,
                     std::span<const CloudObservation> observations, bool velocity_command) {
  const model::Vec2 robot = T_world_robot.translation().head<2>();
  const Eigen::Vector2i origin = master_.window().origin_centred_on(robot);
  master_.move_origin(origin);
  hit_.move_origin(origin);
  // nav2's purgeStaleObservations: older than its persistence (now - stamp > keep) goes.
  std::erase_if(persisted_, [time](const PersistedObservation& kept) {
    return time - kept.time > kept.source.observation_persistence;
  });
  std::vector<CloudObservation> all(observations.begin(), observations.end());
  for (const PersistedObservation& kept : persisted_)
    all.push_back({&kept.cloud, model::Pose3::Identity(), kept.source});
  if (params_.layer == ObstacleLayerKind::obstacle) {
    obstacle_.move_origin(origin);
    obstacle_.update(all);
  } else {
    voxel_.move_origin(origin);
    voxel_.update(all);
    voxel_.project(projection_);
  }
  for (const CloudObservation& observation : observations) {
    if (observation.cloud == nullptr || !(observation.source.observation_persistence > 0.0))
      continue;
    persisted_.push_back({time, world_copy(observation), observation.source});
  }
  const CostGrid& obstacles = obstacle_grid();
  // nav2 resets the master each cycle and the first layer writes it whole.
  master_.cells() = obstacles.cells();
  if (params_.use_hit_layer) {
    decremented_ = hit_.update(obstacles, time, robot, velocity_command);
    hit_.mark(master_);
  }
  inflation_.apply(master_);
}

std::vector<std::uint8_t> remembered_cells(const Costmap& costmap) {
  if (!costmap.params().use_hit_layer) return {};
  const auto& counts = costmap.hit_layer().counts().cells();
  const auto& observed = costmap.obstacle_grid().cells();
  std::vector<std::uint8_t> remembered(counts.size(), 0);
  for (std::size_t i = 0; i < counts.size(); ++i) {
    remembered[i] = counts[i] > 0 && observed[i] != cost::kLethal;
  }
  return remembered;
}

}  // namespace rigdesign::costmap
