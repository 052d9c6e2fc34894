#include "rigdesign/costmap/dijkstra_planner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <utility>

#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {
namespace {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

// Step multiplier of each cell, or a negative value for an impassable one.
std::vector<double> step_weights(const CostGrid& master, const PlannerParams& params) {
  std::vector<double> weights(master.cells().size());
  std::transform(master.cells().begin(), master.cells().end(), weights.begin(),
                 [&](std::uint8_t c) {
                   if (c == cost::kUnknown) {
                     if (!params.allow_unknown) return -1.0;
                     c = params.unknown_cost;
                   }
                   if (c >= cost::kInscribed) return -1.0;
                   return 1.0 + params.cost_weight * c / static_cast<double>(cost::kMaxNonObstacle);
                 });
  return weights;
}

struct Neighbour {
  int dx;
  int dy;
  double length;  // in cells
};

constexpr Neighbour kNeighbours[8] = {
    {1, 0, 1.0},
    {-1, 0, 1.0},
    {0, 1, 1.0},
    {0, -1, 1.0},
    {1, 1, std::numbers::sqrt2},
    {-1, 1, std::numbers::sqrt2},
    {1, -1, std::numbers::sqrt2},
    {-1, -1, std::numbers::sqrt2},
};

}  // namespace

PlannedPath plan_dijkstra(const CostGrid& master, const model::Vec2& start_world,
                          const model::Vec2& goal_world, const PlannerParams& params) {
  PlannedPath path;
  const GridWindow& window = master.window();
  const auto start = window.cell_of(start_world);
  const auto goal = window.cell_of(goal_world);
  if (!start) path.failure = "the start is outside the costmap window";
  if (!goal) path.failure = "the goal is outside the costmap window";
  if (!start || !goal) return path;
  const std::vector<double> weights = step_weights(master, params);
  const std::size_t goal_index = window.index(goal->x, goal->y);
  if (weights[goal_index] < 0) {
    path.failure = "the goal cell is an obstacle or within the inscribed radius of one";
    return path;
  }
  std::vector<double> distance(weights.size(), kUnreached);
  std::vector<std::int32_t> parent(weights.size(), -1);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const std::size_t start_index = window.index(start->x, start->y);
  distance[start_index] = 0.0;
  open.push({0.0, start_index});
  const auto passable = [&](int x, int y) {
    return window.contains(x, y) && weights[window.index(x, y)] >= 0;
  };
  while (!open.empty()) {
    const auto [d, index] = open.top();
    open.pop();
    if (d > distance[index]) continue;  // a stale entry
    if (index == goal_index) break;
    const int x = static_cast<int>(index % window.width);
    const int y = static_cast<int>(index / window.width);
    for (const Neighbour& n : kNeighbours) {
      const int nx = x + n.dx;
      const int ny = y + n.dy;
      if (!passable(nx, ny)) continue;
      if (n.dx != 0 && n.dy != 0 && (!passable(x + n.dx, y) || !passable(x, y + n.dy))) continue;
      const std::size_t next = window.index(nx, ny);
      const double candidate = d + n.length * window.resolution * weights[next];
      if (candidate < distance[next]) {
        distance[next] = candidate;
        parent[next] = static_cast<std::int32_t>(index);
        open.push({candidate, next});
      }
    }
  }
  if (distance[goal_index] == kUnreached) {
    path.failure = "no passable route from the start to the goal";
    return path;
  }
  path.found = true;
  path.cost = distance[goal_index];
  for (std::int64_t i = static_cast<std::int64_t>(goal_index); i >= 0;
       i = parent[static_cast<std::size_t>(i)]) {
    const int x = static_cast<int>(i % window.width);
    const int y = static_cast<int>(i / window.width);
    path.cells.push_back({x, y});
  }
  std::reverse(path.cells.begin(), path.cells.end());
  for (const CellIndex& cell : path.cells) {
    if (!path.waypoints_world.empty()) {
      path.length += (window.centre_of(cell.x, cell.y) - path.waypoints_world.back()).norm();
    }
    path.waypoints_world.push_back(window.centre_of(cell.x, cell.y));
  }
  return path;
}

}  // namespace rigdesign::costmap
