// Issue 6 item 5: the occupancy evaluation's own parts, each against a hand count.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/occupancy/occupancy_evaluation.hpp"
#include "rigdesign/occupancy/occupancy_ground_truth.hpp"
#include "rigdesign/occupancy/occupancy_sweep.hpp"
#include "rigdesign/occupancy/occupancy_trail.hpp"
#include "support/box_mesh.hpp"

using namespace rigdesign;

TEST_CASE("the surface voxeliser finds a box's shell of voxels, counted by hand", "[occupancy]") {
  const occupancy::VoxelLattice lattice{0.1, 0.1, 0.0, 2.0};
  // [0.05, 0.25]^3 spans voxels 0..2 per axis; voxel (1, 1, 1) = [0.1, 0.2]^3 is strictly inside.
  const auto small = occupancy::voxelise_surface(
      test::box_mesh({0.05, 0.05, 0.05}, {0.25, 0.25, 0.25}), lattice, 0.0);
  CHECK(small.size() == 26u);
  CHECK_FALSE(std::binary_search(small.begin(), small.end(), costmap::VoxelKey{1, 1, 1}));
  // [0.05, 0.45]^3: a 5^3 block less its 3^3 interior = 98.
  CHECK(occupancy::voxelise_surface(test::box_mesh({0.05, 0.05, 0.05}, {0.45, 0.45, 0.45}), lattice,
                                    0.0)
            .size() == 98u);
  // Only z >= 0.2 m: the top layer of the small box, 3 x 3.
  const auto top = occupancy::voxelise_surface(
      test::box_mesh({0.05, 0.05, 0.05}, {0.25, 0.25, 0.25}), lattice, 0.2);
  CHECK(top.size() == 9u);
  for (const costmap::VoxelKey& key : top) CHECK(key.z == 2);
  // Anisotropic voxels and a z_min: z = floor((z - 0.05) / 0.05) for a box 0.1..0.2 m high.
  const occupancy::VoxelLattice tall{0.1, 0.05, 0.05, 2.0};
  const auto layered =
      occupancy::voxelise_surface(test::box_mesh({0.01, 0.01, 0.1}, {0.09, 0.09, 0.2}), tall, 0.0);
  // One column, z from 0.1 (layer 1) to 0.2 (layer 3, holding the top face): layers 1, 2, 3.
  REQUIRE(layered.size() == 3u);
  CHECK(layered.front() == costmap::VoxelKey{0, 0, 1});
  CHECK(layered.back() == costmap::VoxelKey{0, 0, 3});
}

TEST_CASE("column masks and their dilation by a radius", "[occupancy]") {
  costmap::GridWindow window{5, 5, 1.0, {-2, -2}};  // lattice -2..2, cell (2, 2) is lattice (0, 0)
  const std::vector<costmap::VoxelKey> keys = {
      {0, 0, 3}, {0, 0, 7}, {9, 9, 0}};  // the last is outside
  const auto columns = occupancy::column_mask(keys, window);
  CHECK(std::count(columns.begin(), columns.end(), 1) == 1);
  CHECK(columns[window.index(2, 2)] == 1);
  // Radius 1: the cell and its 4 edge neighbours; 1.5: the 3 x 3 block (diagonal 1.41).
  auto count = [](const std::vector<std::uint8_t>& m) { return std::count(m.begin(), m.end(), 1); };
  CHECK(count(occupancy::dilate_mask(columns, window, 1.0)) == 5);
  CHECK(count(occupancy::dilate_mask(columns, window, 1.5)) == 9);
  CHECK(count(occupancy::dilate_mask(columns, window, 0.0)) == 1);
}

TEST_CASE("the trail behind a moving object and its length along the path", "[occupancy]") {
  // Five cells of 0.5 m; the object steps from cell 0 to cell 3, a grid that never clears
  // keeps every cell it saw, and cell 4 holds a stray mark the truth never had.
  occupancy::TrailTracker tracker(5, 0.25);
  occupancy::PathOdometer path;
  const model::Vec2 positions[] = {{0, 0}, {1, 0}, {1, 1}, {1, 2}};
  std::vector<std::uint8_t> shown(5, 0);
  shown[4] = 1;
  occupancy::TrailFrame frame;
  for (int k = 0; k < 4; ++k) {
    std::vector<std::uint8_t> truth(5, 0);
    truth[static_cast<std::size_t>(k)] = 1;
    shown[static_cast<std::size_t>(k)] = 1;
    path.record(k, positions[k]);
    frame = tracker.record(k, truth, shown);
  }
  CHECK(frame.ghost_area == Approx(4 * 0.25));  // cells 0, 1, 2 and the stray 4
  CHECK(frame.trail_area == Approx(3 * 0.25));  // the stray is no trail
  CHECK(frame.oldest_trail_time == 0.0);        // cell 0, left after t = 0
  CHECK(frame.trail_p90_time == 0.0);           // rank ceil(0.1 x 3) = 1: the oldest of three
  CHECK(path.length_since(frame.oldest_trail_time) == Approx(3.0));
  CHECK(path.length_since(1.5) == Approx(2.0));  // from the frame at t = 1
  CHECK(path.length_since(-5.0) == Approx(3.0));
  CHECK(path.length_since(3.0) == 0.0);
  // Once the grid clears cells 0 and 1, the trail starts at cell 2 (left after t = 2).
  shown[0] = shown[1] = 0;
  std::vector<std::uint8_t> truth(5, 0);
  truth[3] = 1;
  frame = tracker.record(4, truth, shown);
  CHECK(frame.trail_area == Approx(0.25));
  CHECK(frame.oldest_trail_time == 2.0);
  CHECK(frame.trail_p90_time == 2.0);
  CHECK_THROWS_AS(tracker.record(5, std::vector<std::uint8_t>(4, 0), shown), std::invalid_argument);
}

namespace {

// Shows one fixed voxel far from the object and logs the motion flags it was given.
class FixedMapper final : public occupancy::OccupancyMapper {
 public:
  std::string name() const override { return "fixed"; }
  occupancy::VoxelLattice lattice() const override { return {0.5, 0.5, 0.0, 2.0}; }
  void update(double, std::span<const model::PointCloud>, bool robot_moving) override {
    flags.push_back(robot_moving);
  }
  std::vector<costmap::VoxelKey> occupied() const override { return {{4, 4, 1}}; }
  std::size_t memory_bytes() const override { return sizeof(costmap::VoxelKey); }
  std::vector<bool> flags;
};

model::Scene sliding_box_scene() {
  model::Scene scene;
  scene.name = "sliding box";
  scene.moving.push_back(
      {"box", test::box_mesh({-0.2, -0.2, 0.0}, {0.2, 0.2, 1.0}),
       [](double t) { return model::Pose3(Eigen::Translation3d(-2.0 + 0.5 * t, 0.0, 0.0)); }, 0.0});
  return scene;
}

}  // namespace

TEST_CASE("frames split into the moving and the standing phase", "[occupancy]") {
  FixedMapper mapper;
  occupancy::OccupancyMapper* mappers[] = {&mapper};
  occupancy::OccupancyEvalParams params;
  params.rate = 2.0;
  params.duration = 4.0;
  params.moving_until = 1.0;
  // No sensor here: the box's mesh surface is the truth (paper 3's sensor-point truth would be
  // empty, checked at the end) and the earlier box + margin region counts false positives.
  params.truth = occupancy::TruthKind::mesh_surface;
  params.region = occupancy::ScoringRegion::box_margin;
  const auto runs = occupancy::evaluate_occupancy(sliding_box_scene(), {}, mappers, params);
  REQUIRE(runs.size() == 1u);
  // Frames at 0, 0.5 (moving) and 1.0 .. 3.5 (standing).
  CHECK(runs[0].frames.size() == 8u);
  CHECK(runs[0].moving.frames == 2u);
  CHECK(runs[0].stationary.frames == 6u);
  CHECK(mapper.flags == std::vector<bool>{true, true, false, false, false, false, false, false});
  // The fixed voxel at x, y in [2, 2.5) is a ghost of 0.25 m^2 in every frame, and never near
  // the box (which reaches x = 0 at most), so paper 3's precision is undefined and recall 0.
  CHECK(runs[0].moving.ghost_area == Approx(0.25));
  CHECK(runs[0].stationary.ghost_area_max == Approx(0.25));
  CHECK(runs[0].all.object.recall == 0.0);
  CHECK(std::isnan(runs[0].all.object.precision));
  CHECK(runs[0].all.trail_length_max == 0.0);  // the truth never held that cell
  CHECK_FALSE(runs[0].frames[0].has_master);
  // No sensor: every miss is "never seen".
  CHECK(runs[0].all.seen_not_kept == 0u);
  CHECK(runs[0].all.never_seen > 0u);
  // Paper 3's truth is what the sensors saw of the box: with none, nothing to recall.
  FixedMapper unseen;
  occupancy::OccupancyMapper* unseen_mappers[] = {&unseen};
  params.truth = occupancy::TruthKind::sensor_points;
  params.region = occupancy::ScoringRegion::hull;
  const auto paper3 =
      occupancy::evaluate_occupancy(sliding_box_scene(), {}, unseen_mappers, params);
  CHECK(std::isnan(paper3[0].all.object.recall));
  CHECK(paper3[0].all.never_seen == 0u);
}

TEST_CASE("a scene without a moving object cannot be scored", "[occupancy]") {
  model::Scene still;
  still.name = "still";
  FixedMapper mapper;
  occupancy::OccupancyMapper* mappers[] = {&mapper};
  CHECK_THROWS_AS(occupancy::evaluate_occupancy(still, {}, mappers, {}), std::invalid_argument);
}

TEST_CASE("the sweep's grid is every voxel length with every persistence setting", "[occupancy]") {
  const std::vector<double> voxels = {0.05, 0.1};
  const std::vector<occupancy::PersistenceSetting> settings = {
      {false, 0, 0}, {true, 3, 1500}, {true, 1, 15}};
  occupancy::VoxelMapperParams base;
  base.robot_radius = 0.25;
  const auto grid = occupancy::sweep_grid(voxels, settings, base);
  REQUIRE(grid.size() == 6u);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    CHECK(grid[i].voxel == voxels[i / 3]);
    CHECK(grid[i].persistence == settings[i % 3].enabled);
    CHECK(grid[i].robot_radius == 0.25);
    if (grid[i].persistence) {
      CHECK(grid[i].hit.hit == settings[i % 3].hit);
      CHECK(grid[i].hit.hit_max == settings[i % 3].hit_max);
    }
  }
  CHECK(occupancy::sweep_grid(occupancy::default_sweep_voxels(),
                              occupancy::default_sweep_persistence())
            .size() == 4u * 5u);
  // Each row makes a mapper named after it, on a cubic lattice of its voxel length.
  const auto mappers = occupancy::make_sweep_mappers(grid, model::SourceLocation{"(test)"});
  CHECK(mappers[4]->lattice().resolution == 0.1);
  CHECK(mappers[4]->lattice().z_resolution == 0.1);
  CHECK(mappers[4]->name() == "voxel 0.1 m, hit 3/1500");
}
