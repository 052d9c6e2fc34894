#include "rigdesign/costmap/rolling_grid.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/costmap/hit_layer.hpp"
#include "rigdesign/costmap/rolling_voxel_grid.hpp"

using namespace rigdesign;

namespace {

costmap::GridWindow window_of(int width, int height, double resolution) {
  costmap::GridWindow window;
  window.width = width;
  window.height = height;
  window.resolution = resolution;
  return window;
}

}  // namespace

TEST_CASE("a rolling grid keeps the overlap and resets the cells entering the window",
          "[costmap]") {
  costmap::RollingGrid<int> grid(window_of(4, 3, 1.0), -1);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) grid.at(x, y) = 10 * x + y;
  }
  // Origin moves by (+1, -1): new cell (x, y) is old cell (x + 1, y - 1).
  grid.move_origin({1, -1});
  CHECK(grid.window().origin() == model::Vec2(1.0, -1.0));
  CHECK(grid.at(0, 1) == 10);  // old (1, 0)
  CHECK(grid.at(2, 2) == 31);  // old (3, 1)
  CHECK(grid.at(0, 2) == 11);  // old (1, 1)
  int kept = 0;
  int reset = 0;
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      const bool entering = x == 3 || y == 0;  // old x = 4 or old y = -1
      if (entering) {
        reset += grid.at(x, y) == -1;
      } else {
        kept += grid.at(x, y) == 10 * (x + 1) + (y - 1);
      }
    }
  }
  CHECK(kept == 6);   // (4 - 1) x (3 - 1) overlap
  CHECK(reset == 6);  // 12 - 6
  // A jump longer than the window keeps nothing.
  grid.move_origin({100, 0});
  for (int value : grid.cells()) CHECK(value == -1);
}

TEST_CASE("recentring puts the lattice cell under the robot at the window's centre", "[costmap]") {
  costmap::CostGrid grid(window_of(4, 3, 0.5), 255);
  grid.recentre(model::Vec2(2.2, 0.7));  // lattice cell (4, 1); centre cell (2, 1) -> origin (2, 0)
  CHECK(grid.window().origin_cell == Eigen::Vector2i(2, 0));
  CHECK(grid.window().origin() == model::Vec2(1.0, 0.0));
  const auto cell = grid.window().cell_of(model::Vec2(2.2, 0.7));
  REQUIRE(cell);
  CHECK(*cell == costmap::CellIndex{2, 1});
  CHECK(grid.window().centre_of(2, 1).isApprox(model::Vec2(2.25, 0.75)));
  CHECK_FALSE(grid.window().cell_of(model::Vec2(0.99, 0.7)));
}

TEST_CASE("a rolling voxel grid moves whole columns and keeps lattice keys", "[costmap]") {
  costmap::RollingVoxelGrid grid(window_of(3, 2, 0.1), 0.0, 0.2, 0.1);
  REQUIRE(grid.layers() == 2);
  grid.set(2, 1, 1, costmap::VoxelState::occupied);
  grid.set(0, 0, 0, costmap::VoxelState::free);
  const costmap::VoxelKey key = grid.key_of(2, 1, 1);
  CHECK(key == grid.key_at(model::Vec3(0.25, 0.15, 0.15)));
  grid.move_origin({1, 0});
  CHECK(grid.state(1, 1, 1) == costmap::VoxelState::occupied);
  CHECK(grid.key_of(1, 1, 1) == key);
  CHECK(grid.state(2, 1, 1) == costmap::VoxelState::unknown);    // entered
  CHECK(grid.keys_in_state(costmap::VoxelState::free).empty());  // (0, 0) left the window
  grid.move_origin({3, 0});
  CHECK(grid.keys_in_state(costmap::VoxelState::occupied).empty());
}

TEST_CASE("a band that is a whole number of layers gets exactly that many", "[costmap]") {
  // 2.0 / 0.1 is 19.999... in floating point: still 20 layers, not 21.
  CHECK(costmap::RollingVoxelGrid(window_of(1, 1, 0.1), 0.0, 2.0, 0.1).layers() == 20);
  CHECK(costmap::RollingVoxelGrid(window_of(1, 1, 0.1), 0.0, 2.05, 0.1).layers() == 21);
}

TEST_CASE("the Hit Layer's window keeps counts in the overlap and zeroes new cells", "[costmap]") {
  costmap::HitLayer layer(window_of(5, 5, 0.1), costmap::HitLayerParams{});
  layer.counts().at(3, 2) = 1500;
  layer.counts().at(0, 0) = 7;
  layer.move_origin({2, 0});
  CHECK(layer.counts().at(1, 2) == 1500);
  int non_zero = 0;
  for (std::uint16_t h : layer.counts().cells()) non_zero += h != 0;
  CHECK(non_zero == 1);
  for (int y = 0; y < 5; ++y) {
    CHECK(layer.counts().at(3, y) == 0);
    CHECK(layer.counts().at(4, y) == 0);
  }
}
