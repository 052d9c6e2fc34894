#include "rigdesign/costmap/dwa_planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {
namespace {

// `count` values evenly from low to high (one when the window is a point).
std::vector<double> samples(double low, double high, int count) {
  if (count <= 1 || high - low < 1e-12) return {0.5 * (low + high)};
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back(low + (high - low) * i / (count - 1));
  return values;
}

struct Rollout {
  bool admissible = true;
  double max_cost = 0.0;
  model::Vec2 end = model::Vec2::Zero();
};

// The arc of `command` from `pose` for sim_time, checked every sim_granularity along it.
Rollout roll_out(const CostGrid& master, const Pose2& pose, const VelocityCommand& command,
                 const DwaParams& params) {
  Rollout rollout;
  // Turning on the spot moves no distance: its heading change is checked as an arc of the
  // same length at 0.3 m, a small robot's radius.
  const double travel = std::max(std::abs(command.linear) * params.sim_time,
                                 std::abs(command.angular) * params.sim_time * 0.3);
  const int steps = std::max(1, static_cast<int>(std::ceil(travel / params.sim_granularity)));
  Pose2 at = pose;
  for (int k = 1; k <= steps; ++k) {
    at = integrate_unicycle(pose, command, params.sim_time * k / steps);
    const std::optional<CellIndex> cell = master.window().cell_of(at.position);
    if (!cell) {
      rollout.admissible = false;  // off the local costmap: nothing known to be clear
      return rollout;
    }
    const std::uint8_t cost = master.at(cell->x, cell->y);
    if (cost == cost::kUnknown) continue;  // as the global planner: unknown is passable
    if (cost >= cost::kInscribed) {
      rollout.admissible = false;
      return rollout;
    }
    rollout.max_cost = std::max(rollout.max_cost, static_cast<double>(cost));
  }
  rollout.end = at.position;
  return rollout;
}

double distance_to_path(const model::Vec2& p, const std::vector<model::Vec2>& path) {
  double nearest = path.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  for (const model::Vec2& q : path) nearest = std::min(nearest, (p - q).norm());
  return nearest;
}

}  // namespace

void dynamic_window(const VelocityCommand& current, double period, const DwaParams& params,
                    double linear[2], double angular[2]) {
  const double dv = params.linear_acceleration * period;
  const double dw = params.angular_acceleration * period;
  linear[0] = std::clamp(current.linear - dv, params.min_speed, params.max_speed);
  linear[1] = std::clamp(current.linear + dv, params.min_speed, params.max_speed);
  angular[0] =
      std::clamp(current.angular - dw, -params.max_angular_speed, params.max_angular_speed);
  angular[1] =
      std::clamp(current.angular + dw, -params.max_angular_speed, params.max_angular_speed);
}

DwaResult plan_dwa(const CostGrid& master, const Pose2& pose, const VelocityCommand& current,
                   const std::vector<model::Vec2>& global_path, const model::Vec2& local_goal,
                   double period, const DwaParams& params) {
  DwaResult result;
  dynamic_window(current, period, params, result.window_linear, result.window_angular);
  double best = std::numeric_limits<double>::infinity();
  for (const double v :
       samples(result.window_linear[0], result.window_linear[1], params.linear_samples)) {
    for (const double w :
         samples(result.window_angular[0], result.window_angular[1], params.angular_samples)) {
      if (std::abs(v) < 1e-9 && std::abs(w) < 1e-9) continue;  // standing still goes nowhere
      const VelocityCommand command{v, w};
      ++result.sampled;
      const Rollout rollout = roll_out(master, pose, command, params);
      if (!rollout.admissible) continue;
      ++result.admissible;
      const double cost = params.path_distance_bias * distance_to_path(rollout.end, global_path) +
                          params.goal_distance_bias * (rollout.end - local_goal).norm() +
                          params.occdist_scale * rollout.max_cost;
      if (cost < best) {
        best = cost;
        result.found = true;
        result.command = command;
        result.cost = cost;
      }
    }
  }
  return result;
}

}  // namespace rigdesign::costmap
