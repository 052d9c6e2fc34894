#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/dijkstra_planner.hpp"

using namespace rigdesign;

namespace {

costmap::CostGrid free_grid(int width, int height) {
  costmap::GridWindow window;
  window.width = width;
  window.height = height;
  window.resolution = 1.0;
  return costmap::CostGrid(window, costmap::cost::kFree);
}

}  // namespace

TEST_CASE("Dijkstra finds the hand-solved path through a gap in a wall", "[costmap]") {
  // 5 x 5 cells of 1 m; a wall at x = 2 for y = 0..3, the gap at y = 4.
  costmap::CostGrid grid = free_grid(5, 5);
  for (int y = 0; y < 4; ++y) grid.at(2, y) = costmap::cost::kLethal;
  const costmap::PlannedPath path =
      costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(4.5, 0.5));
  REQUIRE(path.found);
  // By hand: (0,0) -> (1,4) is 1 diagonal + 3 straight; (1,4) -> (2,4) -> (3,4) two straight
  // (a diagonal into or out of the gap would cut the wall's corner at (2,3)); (3,4) -> (4,0)
  // is 1 diagonal + 3 straight: 8 + 2 sqrt(2) m.
  const double expected = 8 + 2 * std::sqrt(2.0);
  CHECK(path.cost == Approx(expected));
  CHECK(path.length == Approx(expected));
  CHECK(path.cells.front() == costmap::CellIndex{0, 0});
  CHECK(path.cells.back() == costmap::CellIndex{4, 0});
  CHECK(std::find(path.cells.begin(), path.cells.end(), costmap::CellIndex{2, 4}) !=
        path.cells.end());
  CHECK(path.waypoints_world.front().isApprox(model::Vec2(0.5, 0.5)));
  CHECK(path.cells.size() == path.waypoints_world.size());
}

TEST_CASE("Dijkstra weighs cell costs: a detour when the straight cell is expensive", "[costmap]") {
  costmap::CostGrid grid = free_grid(3, 3);
  grid.at(1, 2) = 10;             // breaks the tie between the two detours
  costmap::PlannerParams params;  // weight 1 + 3 c / 252
  SECTION("cost 126: straight costs 2.5 + 1 = 3.5 > 2 sqrt(2)") {
    grid.at(1, 1) = 126;
    const costmap::PlannedPath path =
        costmap::plan_dijkstra(grid, model::Vec2(0.5, 1.5), model::Vec2(2.5, 1.5), params);
    REQUIRE(path.found);
    CHECK(path.cells == std::vector<costmap::CellIndex>{{0, 1}, {1, 0}, {2, 1}});
    CHECK(path.cost == Approx(2 * std::sqrt(2.0)));
  }
  SECTION("cost 50: straight costs 1 + 150 / 252 + 1 = 2.595 < 2 sqrt(2)") {
    grid.at(1, 1) = 50;
    const costmap::PlannedPath path =
        costmap::plan_dijkstra(grid, model::Vec2(0.5, 1.5), model::Vec2(2.5, 1.5), params);
    REQUIRE(path.found);
    CHECK(path.cells == std::vector<costmap::CellIndex>{{0, 1}, {1, 1}, {2, 1}});
    CHECK(path.cost == Approx(2.0 + 150.0 / 252.0));
  }
}

TEST_CASE("Dijkstra reports why there is no path", "[costmap]") {
  costmap::CostGrid grid = free_grid(5, 5);
  for (int y = 0; y < 5; ++y) grid.at(2, y) = costmap::cost::kInscribed;
  costmap::PlannedPath path =
      costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(4.5, 0.5));
  CHECK_FALSE(path.found);
  CHECK(path.failure.find("no passable route") != std::string::npos);
  path = costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(2.5, 0.5));
  CHECK(path.failure.find("goal cell is an obstacle") != std::string::npos);
  path = costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(9.5, 0.5));
  CHECK(path.failure.find("outside") != std::string::npos);
  // Unknown cells pass only when allowed.
  for (int y = 0; y < 5; ++y) grid.at(2, y) = costmap::cost::kUnknown;
  CHECK(costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(4.5, 0.5)).found);
  costmap::PlannerParams strict;
  strict.allow_unknown = false;
  CHECK_FALSE(
      costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(4.5, 0.5), strict).found);
  // The start cell may be inside the inscribed radius: the robot is already there.
  grid.at(0, 0) = costmap::cost::kInscribed;
  CHECK(costmap::plan_dijkstra(grid, model::Vec2(0.5, 0.5), model::Vec2(1.5, 3.5)).found);
}
