#pragma once
/// Dijkstra's shortest path on the master grid (paper 2's planner; DESIGN.md section 7):
/// 8-connected cells, each step costing its length times (1 + w c / 252) for the cost c of the
/// cell it enters, so the path keeps off inflated cells when a detour is cheap.
#include <cstdint>
#include <string>
#include <vector>

#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::costmap {

struct PlannerParams {
  /// w: how much a cost of 252 adds to a step, as a multiple of its length.
  double cost_weight = 3.0;
  /// Unknown cells are passable at `unknown_cost` (nav2 NavFn's allow_unknown, which also
  /// prices them as the highest passable cost); otherwise they are impassable.
  bool allow_unknown = true;
  std::uint8_t unknown_cost = 252;
};

struct PlannedPath {
  bool found = false;
  std::vector<model::Vec2>
      waypoints_world;           ///< cell centres from the start cell to the goal cell [m]
  std::vector<CellIndex> cells;  ///< the same cells as window indices
  double length = 0.0;           ///< [m] along the waypoints
  double cost = 0.0;             ///< sum of step costs [m]
  std::string failure;           ///< why there is no path, when !found
};

/// The cheapest path from the cell holding `start_world` to the cell holding `goal_world`.
/// Cells of cost >= cost::kInscribed are impassable (the robot's centre there means a
/// collision), except the start cell, which the robot already occupies; a diagonal step may
/// not cut the corner of an impassable cell. Not found (with the reason) when either point
/// is outside the window, the goal is impassable or walled off. Deterministic: ties go to
/// the lower cell index.
PlannedPath plan_dijkstra(const CostGrid& master, const model::Vec2& start_world,
                          const model::Vec2& goal_world, const PlannerParams& params = {});

}  // namespace rigdesign::costmap
