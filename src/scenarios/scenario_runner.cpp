// The robot-in-the-loop run (issue 6 item 2): sense, update the costmap, plan, follow, check.
#include "rigdesign/scenarios/scenario_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/footprint_collision.hpp"
#include "rigdesign/model/statistics.hpp"
#include "rigdesign/sim/noise_stream.hpp"
#include "rigdesign/sim/ray_caster.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"
#include "scenarios/scenario_setup.hpp"

namespace rigdesign::scenarios {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The scene's objects at time t with their names; `storage` keeps moved copies alive.
std::vector<costmap::NamedMesh> named_meshes_at(const model::Scene& scene, double t,
                                                std::vector<model::TriangleMesh>& storage) {
  std::vector<costmap::NamedMesh> meshes;
  for (const model::SceneObject& object : scene.objects)
    meshes.push_back({object.name, &object.mesh});
  storage.clear();
  storage.reserve(scene.moving.size());
  for (const model::MovingObject& object : scene.moving) {
    storage.emplace_back().append(object.mesh, object.T_world_object(t));
  }
  for (std::size_t i = 0; i < scene.moving.size(); ++i) {
    meshes.push_back({scene.moving[i].name, &storage[i]});
  }
  return meshes;
}

costmap::FootprintCollisionChecker checker_at(const model::Scene& scene, double t,
                                              const costmap::HeightBand& band) {
  std::vector<model::TriangleMesh> storage;
  return costmap::FootprintCollisionChecker(named_meshes_at(scene, t, storage), band);
}

bool passable(std::uint8_t cost, const costmap::PlannerParams& planner) {
  return cost < costmap::cost::kInscribed ||
         (cost == costmap::cost::kUnknown && planner.allow_unknown);
}

// The passable cell nearest `target` within `radius` [m] (ties to the lower cell index).
std::optional<model::Vec2> nearest_passable(const costmap::CostGrid& master,
                                            const model::Vec2& target, double radius,
                                            const costmap::PlannerParams& planner) {
  const costmap::GridWindow& window = master.window();
  const Eigen::Vector2i centre = window.lattice_of(target) - window.origin_cell;
  const int reach = static_cast<int>(std::ceil(radius / window.resolution));
  std::optional<model::Vec2> best;
  double best_distance = radius;
  for (int y = centre.y() - reach; y <= centre.y() + reach; ++y) {
    for (int x = centre.x() - reach; x <= centre.x() + reach; ++x) {
      if (!window.contains(x, y) || !passable(master.at(x, y), planner)) continue;
      const model::Vec2 cell = window.centre_of(x, y);
      const double distance = (cell - target).norm();
      if (distance < best_distance || (!best && distance <= best_distance)) {
        best = cell;
        best_distance = distance;
      }
    }
  }
  return best;
}

// Where the robot heads for: the route point `lookahead` past the robot's projection on the
// current leg, or the passable cell nearest it within `search_radius` (nav2's goal tolerance
// idea); moved on along the leg while none is found; none when the rest of the leg inside the
// window offers none.
std::optional<model::Vec2> local_goal(const model::Vec2& leg_start, const model::Vec2& leg_end,
                                      const model::Vec2& robot, double lookahead,
                                      double search_radius, const costmap::CostGrid& master,
                                      const costmap::PlannerParams& planner) {
  const model::Vec2 leg = leg_end - leg_start;
  const double length = leg.norm();
  const model::Vec2 along = length > 0 ? model::Vec2(leg / length) : model::Vec2::UnitX();
  const double progress = std::clamp((robot - leg_start).dot(along), 0.0, length);
  const double step = master.window().resolution;
  for (double s = std::min(length, progress + lookahead);; s = std::min(length, s + step)) {
    const model::Vec2 target = leg_start + s * along;
    if (!master.window().cell_of(target)) return std::nullopt;
    if (const auto goal = nearest_passable(master, target, search_radius, planner)) return goal;
    if (s >= length) return std::nullopt;
  }
}

}  // namespace

TimeSummary summarize_times(const std::vector<double>& seconds) {
  if (seconds.empty()) return {};
  return {model::median(seconds), model::percentile(seconds, 0.99)};
}

ScenarioResult run_scenario(const ScenarioDefinition& scenario, const model::Rig& rig,
                            const model::SensorLibrary& library, const ScenarioParams& params,
                            const std::function<void(const ScenarioStep&)>& on_update) {
  check_scenario_inputs(rig, library, params);
  const detail::Setup setup = detail::make_setup(rig, library, params);
  costmap::Costmap costmap(setup.costmap);
  const costmap::HeightBand band{params.ground_clearance, rig.body.height};
  const bool static_scene = scenario.scene.moving.empty();
  std::optional<sim::RayCaster> still_caster;
  std::optional<costmap::FootprintCollisionChecker> still_checker;
  if (static_scene) {
    still_caster.emplace(scenario.scene.at(0.0));
    still_checker.emplace(checker_at(scenario.scene, 0.0, band));
  }
  std::vector<std::mt19937_64> streams;
  for (std::size_t i = 0; i < setup.mounts.size(); ++i)
    streams.push_back(sim::noise_stream(params.seed, i));
  sim::SimulationSettings settings;
  settings.add_noise = params.add_noise;

  const int steps_per_update =
      std::max(1, static_cast<int>(std::lround(params.control_rate / params.update_rate)));
  const double dt = 1.0 / params.control_rate;
  const double lookahead =
      std::min(params.goal_lookahead, 0.5 * std::min(setup.costmap.size_x, setup.costmap.size_y) -
                                          2 * setup.costmap.resolution);

  ScenarioResult result;
  costmap::Pose2 pose = scenario.start;
  std::size_t stop = 0;
  bool waiting = false;
  double wait_until = 0.0;
  costmap::VelocityCommand command;
  costmap::PlannedPath path;
  std::vector<model::PointCloud> clouds(setup.mounts.size());
  for (long k = 0;; ++k) {
    const double t = static_cast<double>(k) / params.control_rate;
    result.end_time = t;
    // Ground truth first: the pose reached by the last command.
    const costmap::Clearance clearance =
        static_scene
            ? still_checker->clearance(pose.position, rig.body.radius)
            : checker_at(scenario.scene, t, band).clearance(pose.position, rig.body.radius);
    if (clearance.distance < result.min_clearance) {
      result.min_clearance = clearance.distance;
      result.min_clearance_time = t;
      result.min_clearance_object = clearance.object;
    }
    if (clearance.distance < 0.0) {
      result.collided = true;
      result.collision_time = t;
      result.collision_object = clearance.object;
      result.collision_position = pose.position;
      break;
    }
    // Stops: arrive, wait, leave.
    if (waiting && t >= wait_until - 1e-9) {
      waiting = false;
      ++stop;
    } else if (!waiting &&
               (pose.position - scenario.route[stop].position).norm() < params.goal_tolerance) {
      if (scenario.route[stop].wait > 0.0) {
        waiting = true;
        wait_until = t + scenario.route[stop].wait;
      } else {
        ++stop;
      }
    }
    if (stop >= scenario.route.size()) {
      result.reached_goal = true;
      break;
    }
    if (t > scenario.max_duration) break;

    if (k % steps_per_update == 0) {
      const model::Pose3 T_world_robot = detail::to_pose3(pose);
      std::optional<sim::RayCaster> moving_caster;
      if (!static_scene) moving_caster.emplace(scenario.scene.at(t));
      const sim::RayCaster& caster = static_scene ? *still_caster : *moving_caster;
      std::vector<costmap::CloudObservation> observations;
      for (std::size_t i = 0; i < setup.mounts.size(); ++i) {
        const detail::SimulatedMount& mount = setup.mounts[i];
        clouds[i] =
            sim::simulate_frame(caster, mount.mode, mount.rays,
                                T_world_robot * mount.mount.T_robot_sensor, settings, streams[i]);
        observations.push_back({&clouds[i], model::Pose3::Identity(), setup.mounts[i].source});
      }
      const bool velocity_command = !command.is_zero();
      const Clock::time_point update_start = Clock::now();
      costmap.update(t, T_world_robot, observations, velocity_command);
      result.update_seconds.push_back(seconds_since(update_start));

      model::Vec2 goal = pose.position;
      path = costmap::PlannedPath{};
      if (!waiting) {
        const model::Vec2 leg_start =
            stop == 0 ? scenario.start.position : scenario.route[stop - 1].position;
        const std::optional<model::Vec2> chosen =
            local_goal(leg_start, scenario.route[stop].position, pose.position, lookahead,
                       params.goal_search_radius, costmap.master(), params.planner);
        if (chosen) {
          goal = *chosen;
          const Clock::time_point plan_start = Clock::now();
          path = costmap::plan_dijkstra(costmap.master(), pose.position, goal, params.planner);
          result.planner_seconds.push_back(seconds_since(plan_start));
        }
        if (!path.found) ++result.planner_failures;  // no goal or no path: hold still
      }
      result.trajectory.push_back({t, pose});
      if (on_update) {
        ScenarioStep step;
        step.index = result.updates;
        step.time = t;
        step.pose = pose;
        step.velocity_command = velocity_command;
        step.waiting = waiting;
        step.costmap = &costmap;
        step.path = &path;
        step.goal = goal;
        step.clouds = clouds;
        on_update(step);
      }
      ++result.updates;
    }
    command = waiting || !path.found ? costmap::VelocityCommand{}
                                     : costmap::pursue(path.waypoints_world, pose, params.follower);
    pose = costmap::integrate_unicycle(pose, command, dt);
  }
  result.trajectory.push_back({result.end_time, pose});
  return result;
}

}  // namespace rigdesign::scenarios
