#pragma once
/// The Dynamic Window Approach local planner (Fox, Burgard and Thrun 1997), as ROS's
/// dwa_local_planner runs it: paper 2's local planner (issue 35 item 2). From the current
/// velocity it samples the velocities reachable within one control period (the dynamic
/// window), simulates each as a constant-velocity arc for sim_time, drops every trajectory
/// whose centre enters a cell of cost >= inscribed (the robot would touch an obstacle), and
/// takes the one of lowest cost
///   path_distance_bias x (distance from its end to the global path)
/// + goal_distance_bias x (distance from its end to the local goal)
/// + occdist_scale x (the highest cell cost along it),
/// the cost the ROS wiki states for dwa_local_planner (distances in metres, straight-line here;
/// dwa_local_planner floods them through free cells). Defaults are dwa_local_planner's
/// (cfg/DWAPlanner.cfg): acc_lim_x 2.5 m/s^2, acc_lim_theta 3.2 rad/s^2, max_vel_theta 1 rad/s,
/// sim_time 1.7 s, vx_samples 3, vth_samples 20, biases 32 and 24, occdist_scale 0.01; the
/// speed is the scenario's.
#include <vector>

#include "rigdesign/costmap/path_follower.hpp"
#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::costmap {

struct DwaParams {
  double max_speed = 0.4;             ///< [m/s]
  double min_speed = 0.0;             ///< [m/s] 0: no reversing
  double max_angular_speed = 1.0;     ///< [rad/s]
  double linear_acceleration = 2.5;   ///< [m/s^2]
  double angular_acceleration = 3.2;  ///< [rad/s^2]
  double sim_time = 1.7;              ///< [s] how far ahead each velocity is simulated
  double sim_granularity = 0.025;     ///< [m] (and [rad] / robot radius) between checks
  int linear_samples = 3;             ///< velocities sampled across the window
  int angular_samples = 20;
  double path_distance_bias = 32.0;
  double goal_distance_bias = 24.0;
  double occdist_scale = 0.01;
};

struct DwaResult {
  bool found = false;                     ///< some trajectory is admissible
  VelocityCommand command;                ///< the best one's (zero when none)
  double cost = 0.0;                      ///< its cost
  int sampled = 0;                        ///< trajectories simulated
  int admissible = 0;                     ///< of them, those that stay clear
  double window_linear[2] = {0.0, 0.0};   ///< [m/s] the dynamic window's bounds
  double window_angular[2] = {0.0, 0.0};  ///< [rad/s]
};

/// The dynamic window's bounds from `current` over `period` [s]: [v - a T, v + a T] within
/// [min_speed, max_speed], likewise for the angular speed.
void dynamic_window(const VelocityCommand& current, double period, const DwaParams& params,
                    double linear[2], double angular[2]);

/// The best admissible command from `pose` moving at `current`, towards `local_goal` along
/// `global_path` (world frame), on `master`'s costs; `period` [s] is the control period.
/// Samples run low to high in both speeds and ties keep the first, so the result is
/// deterministic.
DwaResult plan_dwa(const CostGrid& master, const Pose2& pose, const VelocityCommand& current,
                   const std::vector<model::Vec2>& global_path, const model::Vec2& local_goal,
                   double period, const DwaParams& params);

}  // namespace rigdesign::costmap
