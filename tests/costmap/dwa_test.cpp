// Issue 35 item 2: the DWA local planner on hand-built cases. The dynamic window, the
// admissible set and the chosen command are worked out here from the unicycle's arcs, not from
// the planner's own rollout.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/dwa_planner.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

// 8 x 8 m of free 5 cm cells, lattice cell (0, 0) at the world origin's lower-left corner
// shifted so the robot at (0, 0) sits in the middle.
costmap::CostGrid free_map() {
  costmap::GridWindow window;
  window.width = window.height = 160;
  window.resolution = 0.05;
  window.origin_cell = Eigen::Vector2i(-80, -80);
  return costmap::CostGrid(window, costmap::cost::kFree);
}

// A straight path along +x to `length`.
std::vector<model::Vec2> path_ahead(double length) {
  std::vector<model::Vec2> path;
  for (double x = 0.0; x <= length + 1e-9; x += 0.05) path.emplace_back(x, 0.0);
  return path;
}

// Where the arc of (v, w) ends after t: the unicycle from the origin heading +x.
model::Vec2 arc_end(double v, double w, double t) {
  if (std::abs(w) < 1e-12) return {v * t, 0.0};
  return {v / w * std::sin(w * t), v / w * (1.0 - std::cos(w * t))};
}

}  // namespace

TEST_CASE("DWA: the dynamic window is what the accelerations reach in one period", "[costmap]") {
  costmap::DwaParams params;  // 2.5 m/s^2, 3.2 rad/s^2, v in [0, 0.4], |w| <= 1
  double linear[2], angular[2];
  costmap::dynamic_window({0.2, 0.1}, 0.05, params, linear, angular);
  CHECK_THAT(linear[0], WithinAbs(0.2 - 0.125, 1e-12));
  CHECK_THAT(linear[1], WithinAbs(0.2 + 0.125, 1e-12));
  CHECK_THAT(angular[0], WithinAbs(0.1 - 0.16, 1e-12));
  CHECK_THAT(angular[1], WithinAbs(0.1 + 0.16, 1e-12));
  // Near the limits the window is cut by them.
  costmap::dynamic_window({0.35, -0.95}, 0.05, params, linear, angular);
  CHECK_THAT(linear[1], WithinAbs(0.4, 1e-12));
  CHECK_THAT(angular[0], WithinAbs(-1.0, 1e-12));
}

TEST_CASE("DWA: on a free floor it takes the fastest, straightest velocity of the window",
          "[costmap]") {
  // From (0.2, 0): v in {0.075, 0.2, 0.325}, w = -0.16 + 0.32 i / 19. Every arc is clear. The
  // goal (3, 0) lies ahead: the end nearest it and the path is v = 0.325 with the w nearest 0,
  // |w| = 0.16 / 19 (the two are mirror images; the first sampled, the negative, is kept).
  const costmap::DwaParams params;
  const costmap::DwaResult result =
      costmap::plan_dwa(free_map(), {}, {0.2, 0.0}, path_ahead(3.0), {3.0, 0.0}, 0.05, params);
  REQUIRE(result.found);
  CHECK(result.sampled == 3 * 20);
  CHECK(result.admissible == 60);
  CHECK_THAT(result.command.linear, WithinAbs(0.325, 1e-12));
  CHECK_THAT(std::abs(result.command.angular), WithinAbs(0.16 / 19, 1e-12));
  // Its cost, from the arc's end by hand: 32 x (distance to the path) + 24 x (distance to the
  // goal).
  const model::Vec2 end = arc_end(0.325, result.command.angular, 1.7);
  // The path's points are 5 cm apart on y = 0: the nearest is at x rounded to 5 cm.
  const double nearest_x = std::round(end.x() / 0.05) * 0.05;
  const double to_path_point = std::hypot(end.x() - nearest_x, end.y());
  CHECK_THAT(result.cost,
             WithinAbs(32 * to_path_point + 24 * (end - model::Vec2(3, 0)).norm(), 1e-9));
}

TEST_CASE("DWA: a wall ahead rules out the arcs that reach it, it slows down instead",
          "[costmap]") {
  // Cells from x = 0.5 m on are inscribed (the robot's centre there touches the wall). The
  // fastest arcs of the window reach x = (v / w) sin(w T) >= 0.325 / 0.16 sin(0.272) = 0.546 m
  // even at the window's largest turn: all 20 with v = 0.325 end beyond 0.5 m. At v = 0.2 the
  // farthest reach is 0.2 x 1.7 = 0.34 m: all clear. So 40 of 60 are admissible and the best
  // is v = 0.2 with the w nearest 0.
  costmap::CostGrid map = free_map();
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      if (map.window().centre_of(x, y).x() > 0.5) map.at(x, y) = costmap::cost::kInscribed;
  for (int i = 0; i < 20; ++i) {
    const double w = -0.16 + 0.32 * i / 19;
    CHECK(arc_end(0.325, w, 1.7).x() >= 0.5);
    CHECK(arc_end(0.2, w, 1.7).x() < 0.45);
  }
  const costmap::DwaResult result = costmap::plan_dwa(map, {}, {0.2, 0.0}, path_ahead(3.0),
                                                      {3.0, 0.0}, 0.05, costmap::DwaParams{});
  REQUIRE(result.found);
  CHECK(result.admissible == 40);
  CHECK_THAT(result.command.linear, WithinAbs(0.2, 1e-12));
  CHECK_THAT(std::abs(result.command.angular), WithinAbs(0.16 / 19, 1e-12));

  SECTION("walled in on every side: nothing is admissible, the command is zero") {
    for (int y = 0; y < map.height(); ++y)
      for (int x = 0; x < map.width(); ++x)
        if (map.window().centre_of(x, y).norm() > 0.1) map.at(x, y) = costmap::cost::kLethal;
    const costmap::DwaResult blocked = costmap::plan_dwa(map, {}, {0.2, 0.0}, path_ahead(3.0),
                                                         {3.0, 0.0}, 0.05, costmap::DwaParams{});
    CHECK_FALSE(blocked.found);
    CHECK(blocked.command.is_zero());
  }
}
