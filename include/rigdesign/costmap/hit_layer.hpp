#pragma once
/// Paper 1's Hit Layer (section 4, equations 8 and 9; DESIGN.md section 7): an integer count
/// per cell that rises by `hit` (saturating at hit_max) while the obstacle grid below sees the
/// cell occupied and falls by 1 (floored at 0) otherwise; the master grid is lethal wherever
/// the count is positive. The motion condition skips the decrement while the robot stands
/// still, so obstacles that left the sensors' view are kept while it waits.
#include <cstdint>
#include <deque>
#include <span>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::costmap {

struct HitLayerParams {
  int hit = 3;         ///< added per update where the obstacle grid is occupied (paper 1)
  int hit_max = 1500;  ///< the count's ceiling (paper 1)
  /// [m] Paper 1 prints "0.1 mm"; we read it literally as 1e-4 m: with exact (simulated)
  /// poses any threshold above rounding tells waiting from driving. A robot with jittery
  /// localisation needs more (0.1 m, if "mm" was a typo for "m", also works in our scenarios).
  double d_threshold = 1e-4;
  double d_duration = 10.0;  ///< [s] window over which the motion is judged (paper 1)
};

/// Paper 1, eqs. (8) and (9) on flat arrays of the same size: where the observed value is
/// `occupied` (a 2D cost of cost::kLethal by default; pass VoxelState::occupied's value to
/// keep hit counts per voxel), count = min(count + hit, hit_max) (8); elsewhere, only when
/// `decrement`, count = max(count - 1, 0) (9).
void apply_hit_equations(std::span<const std::uint8_t> observed, std::span<std::uint16_t> counts,
                         const HitLayerParams& params, bool decrement,
                         std::uint8_t occupied = cost::kLethal);

/// The motion condition: the robot counts as moving when it was given a velocity command or
/// when some recorded position of the last d_duration seconds lies d_threshold or more from
/// its current one. Before d_duration has passed, the positions seen so far count.
class MotionMonitor {
 public:
  explicit MotionMonitor(const HitLayerParams& params = {}) : params_(params) {}
  /// Records the robot's position [m] at `time` [s] (non-decreasing).
  void record(double time, const model::Vec2& position_world);
  /// True while the robot counts as moving (see the class comment).
  bool moving(bool velocity_command) const;

 private:
  struct Sample {
    double time;
    model::Vec2 position;
  };
  HitLayerParams params_;
  std::deque<Sample> samples_;
};

class HitLayer {
 public:
  HitLayer() = default;
  /// Counts start at 0. Parameters are checked by check_costmap_params.
  HitLayer(const GridWindow& window, const HitLayerParams& params);

  /// One step: records the robot position, then applies eqs. (8) and (9) to `obstacles` (a grid
  /// on this layer's window), decrementing only when the motion condition says the robot
  /// moves. Returns whether it decremented.
  bool update(const CostGrid& obstacles, double time, const model::Vec2& robot_world,
              bool velocity_command);

  /// Sets cost::kLethal in `master` (on this layer's window) wherever the count is positive.
  void mark(CostGrid& master) const;

  void recentre(const model::Vec2& centre_world) { counts_.recentre(centre_world); }
  void move_origin(const Eigen::Vector2i& origin_cell) { counts_.move_origin(origin_cell); }

  const RollingGrid<std::uint16_t>& counts() const { return counts_; }
  RollingGrid<std::uint16_t>& counts() { return counts_; }
  const HitLayerParams& params() const { return params_; }

 private:
  HitLayerParams params_;
  MotionMonitor motion_;
  RollingGrid<std::uint16_t> counts_;
};

}  // namespace rigdesign::costmap
