#include "rigdesign/costmap/hit_layer.hpp"

#include <catch2/catch.hpp>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/rolling_voxel_grid.hpp"

using namespace rigdesign;

namespace {

// Runs eqs. (8) and (9) on one cell through a sequence of observations (true = occupied).
std::vector<int> counts_over(const std::vector<bool>& occupied,
                             const costmap::HitLayerParams& params, int start = 0) {
  std::vector<std::uint16_t> h{static_cast<std::uint16_t>(start)};
  std::vector<int> seen;
  for (bool o : occupied) {
    const std::vector<std::uint8_t> cost{o ? costmap::cost::kLethal : costmap::cost::kFree};
    costmap::apply_hit_equations(cost, h, params, true);
    seen.push_back(h[0]);
  }
  return seen;
}

costmap::GridWindow small_window() {
  costmap::GridWindow window;
  window.width = 3;
  window.height = 1;
  window.resolution = 0.1;
  return window;
}

}  // namespace

TEST_CASE("equation 8 adds hit per occupied update and saturates at hit_max", "[costmap]") {
  costmap::HitLayerParams params;
  params.hit_max = 10;
  // 0 + 3 + 3 + 3 = 9, then min(12, 10) = 10, and it stays there.
  CHECK(counts_over({true, true, true, true, true}, params) == std::vector<int>{3, 6, 9, 10, 10});
  // Paper values: 500 occupied updates reach 1500, the 501st stays at 1500.
  costmap::HitLayerParams paper;
  CHECK(counts_over(std::vector<bool>(501, true), paper).back() == 1500);
  CHECK(counts_over(std::vector<bool>(499, true), paper).back() == 1497);
}

TEST_CASE("equation 9 takes 1 per free update and floors at 0", "[costmap]") {
  costmap::HitLayerParams params;
  CHECK(counts_over({false, false, false}, params, 2) == std::vector<int>{1, 0, 0});
  // One sighting (3) outlives two free updates, not three; unknown counts as not occupied.
  const std::vector<std::uint8_t> unknown{costmap::cost::kUnknown};
  std::vector<std::uint16_t> h{0};
  CHECK(counts_over({true, false, false, false}, params) == std::vector<int>{3, 2, 1, 0});
  h[0] = 5;
  costmap::apply_hit_equations(unknown, h, params, true);
  CHECK(h[0] == 4);
  // Without the decrement (robot still) nothing falls; occupied cells still rise.
  costmap::apply_hit_equations(unknown, h, params, false);
  CHECK(h[0] == 4);
  const std::vector<std::uint8_t> lethal{costmap::cost::kLethal};
  costmap::apply_hit_equations(lethal, h, params, false);
  CHECK(h[0] == 7);
}

TEST_CASE("the motion condition judges the last d_duration seconds", "[costmap]") {
  costmap::HitLayerParams params;  // d_threshold 0.1 mm, d_duration 10 s
  costmap::MotionMonitor monitor(params);
  // Drives 1 m along x in the first second (samples every 0.5 s), then stands still.
  for (int i = 0; i <= 22; ++i) {
    const double t = 0.5 * i;
    monitor.record(t, model::Vec2(std::min(t, 1.0), 0.0));
    if (t == 10.5) CHECK(monitor.moving(false));  // the sample at 0.5 s (x = 0.5) is in the window
    if (t == 11.0) CHECK_FALSE(monitor.moving(false));  // from 1 s on it stood at x = 1
  }
  CHECK(monitor.moving(true));                         // a velocity command always counts as moving
  monitor.record(11.5, model::Vec2(1.0 + 2e-4, 0.0));  // 0.2 mm > 0.1 mm
  CHECK(monitor.moving(false));
}

TEST_CASE("a stationary robot keeps Hit Layer cells, a moving one lets them decay", "[costmap]") {
  costmap::HitLayerParams params;
  costmap::HitLayer layer(small_window(), params);
  costmap::CostGrid obstacles(small_window(), costmap::cost::kFree);
  obstacles.at(1, 0) = costmap::cost::kLethal;
  double t = 0.0;
  CHECK_FALSE(layer.update(obstacles, t, model::Vec2::Zero(), false));  // standing: no decrement
  CHECK(layer.counts().at(1, 0) == 3);
  obstacles.at(1, 0) = costmap::cost::kFree;  // the obstacle leaves the sensors' view
  for (int step = 0; step < 50; ++step)
    layer.update(obstacles, t += 0.1, model::Vec2::Zero(), false);
  CHECK(layer.counts().at(1, 0) == 3);
  costmap::CostGrid master(small_window(), costmap::cost::kFree);
  layer.mark(master);
  CHECK(master.at(1, 0) == costmap::cost::kLethal);
  CHECK(master.at(0, 0) == costmap::cost::kFree);
  // Driving: three updates take it to 0.
  CHECK(layer.update(obstacles, t += 0.1, model::Vec2(0.05, 0.0), false));
  layer.update(obstacles, t += 0.1, model::Vec2(0.10, 0.0), false);
  CHECK(layer.counts().at(1, 0) == 1);
  layer.update(obstacles, t += 0.1, model::Vec2(0.15, 0.0), false);
  CHECK(layer.counts().at(1, 0) == 0);
}

TEST_CASE("the Hit equations also keep counts per voxel", "[costmap]") {
  // Voxel states occupied, free, unknown: the occupied one rises, the others fall.
  const std::vector<std::uint8_t> voxels{static_cast<std::uint8_t>(costmap::VoxelState::occupied),
                                         static_cast<std::uint8_t>(costmap::VoxelState::free),
                                         static_cast<std::uint8_t>(costmap::VoxelState::unknown)};
  std::vector<std::uint16_t> h{0, 5, 5};
  costmap::apply_hit_equations(voxels, h, costmap::HitLayerParams{}, true,
                               static_cast<std::uint8_t>(costmap::VoxelState::occupied));
  CHECK(h == std::vector<std::uint16_t>{3, 4, 4});
}
