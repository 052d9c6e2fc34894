#include "rigdesign/costmap/voxel_layer.hpp"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/obstacle_layer.hpp"

using namespace rigdesign;

namespace {

// 10 x 10 cells of 0.1 m over [0, 1] x [0, 1], z in [0, 0.5) in 5 layers of 0.1 m.
costmap::GridWindow unit_window() {
  costmap::GridWindow window;
  window.width = 10;
  window.height = 10;
  window.resolution = 0.1;
  return window;
}

costmap::VoxelLayerParams band() {
  costmap::VoxelLayerParams params;
  params.z_max = 0.5;
  params.z_resolution = 0.1;
  return params;
}

model::PointCloud cloud_seen_from(const model::Point3f& origin,
                                  std::vector<model::Point3f> points) {
  model::PointCloud cloud;
  cloud.origin = origin;
  cloud.points = std::move(points);
  return cloud;
}

costmap::CloudObservation observe(const model::PointCloud& cloud) {
  costmap::CloudObservation observation;
  observation.cloud = &cloud;
  observation.source.min_obstacle_height = 0.0;
  return observation;
}

std::vector<costmap::VoxelState> row_states(const costmap::VoxelLayer& layer, int y, int z) {
  std::vector<costmap::VoxelState> states;
  for (int x = 0; x < 10; ++x) states.push_back(layer.grid().state(x, y, z));
  return states;
}

// Every voxel the open segment a -> b passes through, found independently of the walk: split
// the segment at every plane crossing and take the voxel of each piece's midpoint.
std::set<std::array<int, 3>> voxels_crossed(const model::Vec3& a, const model::Vec3& b) {
  std::vector<double> cuts{0.0, 1.0};
  for (int k = 0; k < 3; ++k) {
    const double lo = std::min(a[k], b[k]);
    const double hi = std::max(a[k], b[k]);
    for (double plane = std::ceil(lo); plane < hi; plane += 1.0)
      cuts.push_back((plane - a[k]) / (b[k] - a[k]));
  }
  std::sort(cuts.begin(), cuts.end());
  std::set<std::array<int, 3>> voxels;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const model::Vec3 mid = a + (b - a) * (0.5 * (cuts[i] + cuts[i + 1]));
    voxels.insert({static_cast<int>(std::floor(mid.x())), static_cast<int>(std::floor(mid.y())),
                   static_cast<int>(std::floor(mid.z()))});
  }
  return voxels;
}

}  // namespace

TEST_CASE("the voxel layer clears a ray's voxels and marks its end voxel", "[costmap]") {
  costmap::VoxelLayer layer(unit_window(), band());
  // Along +x in row y = 5, layer z = 2: from voxel 0 to voxel 7.
  const model::PointCloud cloud = cloud_seen_from({0.05f, 0.55f, 0.25f}, {{0.75f, 0.55f, 0.25f}});
  layer.insert(observe(cloud));
  using S = costmap::VoxelState;
  CHECK(row_states(layer, 5, 2) == std::vector<S>{S::free, S::free, S::free, S::free, S::free,
                                                  S::free, S::free, S::occupied, S::unknown,
                                                  S::unknown});
  CHECK(row_states(layer, 5, 1) == std::vector<S>(10, S::unknown));
  CHECK(layer.grid().keys_in_state(S::free).size() == 7);
}

TEST_CASE("the voxel walk visits exactly the voxels a segment crosses", "[costmap]") {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> xy(0.0, 1.0);
  std::uniform_real_distribution<double> z(0.0, 0.5);
  for (int trial = 0; trial < 200; ++trial) {
    costmap::VoxelLayer layer(unit_window(), band());
    const model::Vec3 a(xy(rng), xy(rng), z(rng));
    const model::Vec3 b(xy(rng), xy(rng), z(rng));
    const model::PointCloud cloud = cloud_seen_from(a.cast<float>(), {b.cast<float>()});
    costmap::CloudObservation observation = observe(cloud);
    observation.source.marking = false;
    observation.source.raytrace_max_range = 10.0;
    layer.insert(observation);
    // In cell units (0.1 m cells, corner at the origin), from the float coordinates used.
    const model::Vec3 a_cells = a.cast<float>().cast<double>() / 0.1;
    const model::Vec3 b_cells = b.cast<float>().cast<double>() / 0.1;
    std::set<std::array<int, 3>> expected = voxels_crossed(a_cells, b_cells);
    expected.erase(
        {static_cast<int>(std::floor(b_cells.x())), static_cast<int>(std::floor(b_cells.y())),
         static_cast<int>(std::floor(b_cells.z()))});  // the end voxel is a hit, not cleared
    std::set<std::array<int, 3>> cleared;
    for (const costmap::VoxelKey& key : layer.grid().keys_in_state(costmap::VoxelState::free))
      cleared.insert({key.x, key.y, key.z});
    INFO("trial " << trial);
    CHECK(cleared == expected);
  }
}

TEST_CASE("a cloud cannot clear its own new marks: clear every ray, then mark", "[costmap]") {
  costmap::VoxelLayer layer(unit_window(), band());
  // The ray to the far point (voxel 7) passes through the near point's voxel 3; the near
  // point comes first, so marking point by point would let the far ray erase it.
  const model::PointCloud both =
      cloud_seen_from({0.05f, 0.55f, 0.25f}, {{0.35f, 0.55f, 0.25f}, {0.75f, 0.55f, 0.25f}});
  layer.insert(observe(both));
  CHECK(layer.grid().state(3, 5, 2) == costmap::VoxelState::occupied);
  CHECK(layer.grid().state(7, 5, 2) == costmap::VoxelState::occupied);
  // A later cloud whose ray crosses voxel 3 clears it: marks only outlive their own cloud.
  const model::PointCloud far_only =
      cloud_seen_from({0.05f, 0.55f, 0.25f}, {{0.75f, 0.55f, 0.25f}});
  layer.insert(observe(far_only));
  CHECK(layer.grid().state(3, 5, 2) == costmap::VoxelState::free);
  CHECK(layer.grid().state(7, 5, 2) == costmap::VoxelState::occupied);
}

TEST_CASE("ranges and the height band limit marking and clearing", "[costmap]") {
  costmap::VoxelLayer layer(unit_window(), band());
  const model::PointCloud cloud =
      cloud_seen_from({0.05f, 0.55f, 0.25f}, {{0.95f, 0.55f, 0.25f}, {0.05f, 0.25f, 0.02f}});
  costmap::CloudObservation observation = observe(cloud);
  observation.source.obstacle_max_range = 0.5;    // the far point (0.9 m away) does not mark
  observation.source.raytrace_max_range = 0.62;   // clearing stops at x = 0.67, in voxel 6
  observation.source.min_obstacle_height = 0.05;  // the low point (z = 0.02) does not mark
  layer.insert(observation);
  using S = costmap::VoxelState;
  CHECK(row_states(layer, 5, 2) == std::vector<S>{S::free, S::free, S::free, S::free, S::free,
                                                  S::free, S::free, S::unknown, S::unknown,
                                                  S::unknown});
  CHECK(layer.grid().keys_in_state(S::occupied).empty());
  // The low point's ray still clears in 3D (it crossed those voxels): from y = 0.55 down to
  // y = 0.25 and z = 0.25 down to 0.02 it runs through column x = 0.
  CHECK(layer.grid().state(0, 2, 0) == S::unknown);  // its own end voxel is left alone
  CHECK(layer.grid().state(0, 4, 1) == S::free);
}

TEST_CASE("columns project by paper 2's rule: any occupied, else more than 4 unknown",
          "[costmap]") {
  costmap::GridWindow window = unit_window();
  window.width = 4;
  window.height = 1;
  costmap::VoxelLayerParams params;
  params.z_max = 1.0;
  params.z_resolution = 0.1;  // 10 voxels per column
  costmap::VoxelLayer layer(window, params);
  auto set_column = [&](int x, int unknown, int occupied) {
    for (int z = 0; z < 10; ++z) {
      const costmap::VoxelState state = z < unknown              ? costmap::VoxelState::unknown
                                        : z < unknown + occupied ? costmap::VoxelState::occupied
                                                                 : costmap::VoxelState::free;
      layer.grid().set(x, 0, z, state);
    }
  };
  set_column(0, 5, 0);  // 5 unknown > 4: unknown
  set_column(1, 4, 0);  // 4 unknown: free
  set_column(2, 9, 1);  // one occupied wins over 9 unknown
  set_column(3, 0, 0);  // all free
  costmap::CostGrid projected;
  layer.project(projected);
  REQUIRE(projected.width() == 4);
  CHECK(projected.at(0, 0) == costmap::cost::kUnknown);
  CHECK(projected.at(1, 0) == costmap::cost::kFree);
  CHECK(projected.at(2, 0) == costmap::cost::kLethal);
  CHECK(projected.at(3, 0) == costmap::cost::kFree);
}

TEST_CASE("the 2D obstacle layer clears under a ray that passes over a low obstacle", "[costmap]") {
  costmap::ObstacleLayer layer(unit_window(), costmap::ObstacleLayerParams{true});
  // A low camera marks the foam edge at x = 0.35; then a lidar at 1 m sees the wall at
  // x = 0.75 over it: in 2D its ray crosses the foam's cell and clears it.
  const model::PointCloud camera = cloud_seen_from({0.05f, 0.55f, 0.3f}, {{0.35f, 0.55f, 0.4f}});
  layer.update(std::vector<costmap::CloudObservation>{observe(camera)});
  CHECK(layer.grid().at(3, 5) == costmap::cost::kLethal);
  CHECK(layer.grid().at(1, 5) == costmap::cost::kFree);
  CHECK(layer.grid().at(5, 5) == costmap::cost::kUnknown);
  const model::PointCloud lidar = cloud_seen_from({0.05f, 0.55f, 1.0f}, {{0.75f, 0.55f, 1.0f}});
  layer.update(std::vector<costmap::CloudObservation>{observe(lidar)});
  CHECK(layer.grid().at(3, 5) == costmap::cost::kFree);
  CHECK(layer.grid().at(7, 5) == costmap::cost::kLethal);
  // A clearing-only source leaves marks alone at its end points.
  costmap::CloudObservation clearing_only = observe(lidar);
  clearing_only.source.marking = false;
  layer.grid().at(7, 5) = costmap::cost::kFree;
  layer.update(std::vector<costmap::CloudObservation>{clearing_only});
  CHECK(layer.grid().at(7, 5) == costmap::cost::kFree);
}

TEST_CASE("observations in the robot frame are placed by T_world_cloud", "[costmap]") {
  costmap::VoxelLayer layer(unit_window(), band());
  const model::PointCloud robot_frame = cloud_seen_from({0.0f, 0.0f, 0.25f}, {{0.3f, 0.0f, 0.25f}});
  costmap::CloudObservation observation = observe(robot_frame);
  // Robot at (0.55, 0.15) facing +y: the point 0.3 m ahead lands at (0.55, 0.45, 0.25).
  observation.T_world_cloud =
      model::Pose3(Eigen::Translation3d(0.55, 0.15, 0.0) *
                   Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitZ()));
  layer.insert(observation);
  const auto occupied = layer.grid().keys_in_state(costmap::VoxelState::occupied);
  REQUIRE(occupied.size() == 1);
  CHECK(occupied[0] == costmap::VoxelKey{5, 4, 2});
}
