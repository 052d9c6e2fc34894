// The robot-in-the-loop run (issue 6 item 2): sense, update the costmap, plan, follow, check.
#include "rigdesign/scenarios/scenario_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <set>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/footprint_collision.hpp"
#include "rigdesign/filters/floor_removal.hpp"
#include "rigdesign/filters/radius_outlier.hpp"
#include "rigdesign/model/format_number.hpp"
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

// The scene's still objects with their names.
std::vector<costmap::NamedMesh> still_meshes(const model::Scene& scene) {
  std::vector<costmap::NamedMesh> meshes;
  for (const model::SceneObject& object : scene.objects)
    meshes.push_back({object.name, &object.mesh});
  return meshes;
}

// Every triangle of the still objects, for the ray caster built once per run.
model::TriangleMesh still_mesh(const model::Scene& scene) {
  model::TriangleMesh mesh;
  for (const model::SceneObject& object : scene.objects) mesh.append(object.mesh);
  return mesh;
}

// The moving objects' own clocks: scene time, except that one which gives way stands still
// while the robot's centre is within its distance. Recorded at every control step; a frame
// captured between two steps sees each object at the earlier step's clock plus the time since
// (exact for objects that never wait; off by at most one 50 ms step for one that just stopped).
class ObjectClocks {
 public:
  explicit ObjectClocks(const model::Scene& scene)
      : scene_(scene), clocks_(scene.moving.size(), 0.0) {}
  void record(double t) { history_.push_back({t, clocks_}); }
  /// To scene time `t_next`, the robot standing at `robot` now.
  void advance(double t_next, double dt, const model::Vec2& robot) {
    for (std::size_t i = 0; i < clocks_.size(); ++i) {
      const model::MovingObject& object = scene_.moving[i];
      if (!(object.gives_way_within > 0.0)) {
        clocks_[i] = t_next;
        continue;
      }
      const model::Vec2 at = object.T_world_object(clocks_[i]).translation().head<2>();
      if ((at - robot).norm() >= object.gives_way_within) clocks_[i] += dt;
    }
  }
  const std::vector<double>& now() const { return clocks_; }
  std::vector<double> at(double t) const {
    const auto after = std::upper_bound(history_.begin(), history_.end(), t,
                                        [](double time, const Step& s) { return time < s.t; });
    if (after == history_.begin()) return clocks_;
    const Step& step = *std::prev(after);
    std::vector<double> clocks = step.clocks;
    for (double& clock : clocks) clock += t - step.t;
    return clocks;
  }

 private:
  struct Step {
    double t;
    std::vector<double> clocks;
  };
  const model::Scene& scene_;
  std::vector<double> clocks_;
  std::vector<Step> history_;
};

// The moving objects at their clocks: `storage` keeps the moved copies alive for the named
// meshes.
std::vector<costmap::NamedMesh> moving_meshes_at(const model::Scene& scene,
                                                 const std::vector<double>& clocks,
                                                 std::vector<model::TriangleMesh>& storage) {
  storage.clear();
  storage.reserve(scene.moving.size());
  for (std::size_t i = 0; i < scene.moving.size(); ++i)
    storage.emplace_back().append(scene.moving[i].mesh, scene.moving[i].T_world_object(clocks[i]));
  std::vector<costmap::NamedMesh> meshes;
  for (std::size_t i = 0; i < scene.moving.size(); ++i)
    meshes.push_back({scene.moving[i].name, &storage[i]});
  return meshes;
}

model::TriangleMesh moving_mesh_at(const model::Scene& scene, const std::vector<double>& clocks) {
  model::TriangleMesh mesh;
  for (std::size_t i = 0; i < scene.moving.size(); ++i)
    mesh.append(scene.moving[i].mesh, scene.moving[i].T_world_object(clocks[i]));
  return mesh;
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

// The robot's poses and commands at every control step so far: where it was when a sensor
// captured a frame between two steps.
class PoseHistory {
 public:
  void record(double t, const costmap::Pose2& pose, const costmap::VelocityCommand& command) {
    steps_.push_back({t, pose, command});
  }
  bool empty() const { return steps_.empty(); }
  /// The pose at time `t` [s], at most the last recorded step's time + its step; before the
  /// first step, the first pose.
  costmap::Pose2 at(double t) const {
    const auto after = std::upper_bound(steps_.begin(), steps_.end(), t,
                                        [](double time, const Step& s) { return time < s.t; });
    if (after == steps_.begin()) return steps_.front().pose;
    const Step& step = *std::prev(after);
    return costmap::integrate_unicycle(step.pose, step.command, t - step.t);
  }

 private:
  struct Step {
    double t;
    costmap::Pose2 pose;
    costmap::VelocityCommand command;
  };
  std::vector<Step> steps_;
};

// Paper 2's deadlock handling: stuck (no plan or no admissible velocity for the patience, or
// no progress towards the stop for three patiences), stop, clear the obstacles beyond 0.5 m and
// turn 360 degrees; stuck again on the same leg, clear everything and turn again; a third time,
// give up.
struct Recovery {
  double stuck_since = -1.0;    // [s] since when no plan or velocity was found; < 0: found
  int level = 0;                // recoveries on the current leg
  std::size_t leg = 0;          // the route stop they were for
  double turning_until = -1.0;  // [s] end of the current recovery turn
  double closest = 0.0;         // [m] the robot's least distance to the stop since progress began
  double anchor_time = 0.0;     // [s] when it last came this much closer
};

// [m] coming this much closer to the stop counts as progress; without it for this many
// patiences the robot is stuck too: it stands at a substitute local goal short of a walled-off
// stop, or rocks to and fro in front of an obstacle it cannot pass.
constexpr double kProgress = 0.1;
constexpr double kProgressPatiences = 3.0;

// Returns true when the recoveries for the current stop are exhausted: it is unreachable.
bool recover_if_stuck(Recovery& recovery, bool blocked, bool waiting, double t, std::size_t stop,
                      const model::Vec2& stop_position, const costmap::Pose2& pose,
                      costmap::Costmap& costmap, const ScenarioParams& params,
                      ScenarioResult& result) {
  const double distance = (stop_position - pose.position).norm();
  if (stop != recovery.leg) {  // a stop reached: a new leg starts without recoveries
    recovery.leg = stop;
    recovery.level = 0;
    recovery.closest = distance;
    recovery.anchor_time = t;
  }
  if (waiting || t < recovery.turning_until || distance < recovery.closest - kProgress) {
    recovery.closest = distance;
    recovery.anchor_time = t;
  }
  if (!blocked) recovery.stuck_since = -1.0;
  if (blocked && recovery.stuck_since < 0.0) recovery.stuck_since = t;
  const bool no_plan = blocked && t - recovery.stuck_since >= params.deadlock_patience;
  const bool no_progress =
      t - recovery.anchor_time >= kProgressPatiences * params.deadlock_patience;
  if (!no_plan && !no_progress) return false;
  recovery.stuck_since = -1.0;
  recovery.closest = distance;
  recovery.anchor_time = t;
  if (recovery.level >= 2) return true;
  ++recovery.level;
  ++result.recoveries;
  costmap.clear_outside(pose.position, recovery.level == 1 ? params.deadlock_clear_radius : 0.0);
  recovery.turning_until = t + 2.0 * std::numbers::pi / params.follower.max_angular_speed;
  return false;
}

// World cells [costmap resolution] where the negative-obstacle stage put virtual points: the
// drops the costmap was told of, for naming why a stop is unreachable.
using CellSet = std::set<std::pair<long, long>>;

std::pair<long, long> cell_of(const model::Vec2& p, double resolution) {
  return {static_cast<long>(std::floor(p.x() / resolution)),
          static_cast<long>(std::floor(p.y() / resolution))};
}

// Paper 2's negative obstacles on a world-frame frame (floor at z = 0); the virtual points,
// which the stage appends after the others, are recorded in `drops`.
model::PointCloud with_negative_obstacles(const model::PointCloud& frame, double resolution,
                                          CellSet& drops) {
  const model::NegativeObstacleParams stage;
  const std::size_t below = static_cast<std::size_t>(
      std::count_if(frame.points.begin(), frame.points.end(),
                    [&](const model::Point3f& p) { return p.z() < stage.below; }));
  model::PointCloud marked = filters::mark_negative_obstacles(frame, stage);
  for (std::size_t i = marked.size() - below; i < marked.size(); ++i) {
    const model::Point3f& p = marked.points[i];
    drops.insert(cell_of(model::Vec2(p.x(), p.y()), resolution));
  }
  return marked;
}

// Why route stop `stop` is unreachable: a marked drop within reach of the straight way there
// (the nearest to the robot), else the recoveries that found no way.
std::string unreachable_reason(std::size_t stop, const std::string& name, const model::Vec2& robot,
                               const model::Vec2& goal, const CellSet& drops, double resolution,
                               double reach, const ScenarioParams& params) {
  const std::string which =
      "route stop " + std::to_string(stop + 1) + (name.empty() ? "" : " (" + name + ")");
  const model::Vec2 way = goal - robot;
  const double length = way.norm();
  std::optional<model::Vec2> nearest;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (const auto& [x, y] : drops) {
    const model::Vec2 centre((static_cast<double>(x) + 0.5) * resolution,
                             (static_cast<double>(y) + 0.5) * resolution);
    const double along =
        length > 0 ? std::clamp((centre - robot).dot(way) / length, 0.0, length) : 0.0;
    const model::Vec2 closest = length > 0 ? model::Vec2(robot + along * way / length) : robot;
    if ((centre - closest).norm() > reach) continue;
    const double distance = (centre - robot).norm();
    if (distance < nearest_distance) {
      nearest_distance = distance;
      nearest = centre;
    }
  }
  const std::string recoveries = "after two recoveries (cleared the costmap beyond " +
                                 model::format_number(params.deadlock_clear_radius) +
                                 " m, then entirely, turning 360 deg each time)";
  if (nearest) {
    return which + " refused: a drop (stairs or a hole) the negative-obstacle stage marked at (" +
           model::format_number(nearest->x(), 3) + ", " + model::format_number(nearest->y(), 3) +
           ") m lies on the way, and no way round it was found " + recoveries;
  }
  return which + " unreachable: no way there " + recoveries;
}

// One scenario run: what it reads, and the state one control step hands to the next (the
// robot's pose and command, the leg and stop it is on, the frames and costmap it holds, the
// result so far). The state is named once here rather than passed between the steps, which
// run_scenario calls in the order the robot lives them: judge where the last command took it,
// then, at every costmap update, sense, update and plan, then act.
struct ScenarioLoop {
  ScenarioLoop(const ScenarioDefinition& run_definition, const model::Rig& run_rig,
               const ScenarioParams& run_params, const detail::Setup& run_setup,
               const std::function<void(const ScenarioStep&)>& run_on_update);

  // One control step `k`; false when the run ends with it.
  bool step(long k);
  // The result, once the loop has ended.
  ScenarioResult finish();

  bool judge(double t);
  bool collided(double t);
  bool drove_off(double t);
  void pass_stops(double t);
  std::vector<costmap::CloudObservation> sense(double t);
  void sense_mount(std::size_t i, double t, std::vector<costmap::CloudObservation>& observations);
  model::PointCloud cast_frame(std::size_t i, long index);
  void update(double t, std::span<const costmap::CloudObservation> observations,
              bool velocity_command);
  void plan();
  void publish(double t, bool velocity_command);
  bool act(double t);
  bool choose_command(double t);
  bool refuse_stop(double t);
  void drive(long k, double t);
  void start_leg(double t);

  const ScenarioDefinition& scenario;
  const model::Rig& rig;
  const ScenarioParams& params;
  const detail::Setup& setup;
  const std::function<void(const ScenarioStep&)>& on_update;

  costmap::Costmap costmap;
  const costmap::HeightBand band;
  const bool static_scene;
  // The still objects' tree and outlines are built once; the moving ones at each instant.
  const sim::RayCaster still_caster;
  const costmap::FootprintCollisionChecker still_checker;
  std::vector<std::mt19937_64> streams;  // one per mount
  sim::SimulationSettings settings;
  const int steps_per_update;
  const double dt;
  const double lookahead;
  const double resolution;
  costmap::DwaParams dwa;

  ScenarioResult result;
  CellSet drop_marks;
  // The leg being driven: where and when it started, how far the robot has come on it.
  model::Vec2 leg_start;
  double leg_start_time = 0.0;
  double leg_distance = 0.0;
  bool touched_by_walker = false;
  ObjectClocks clocks;
  // Frames simulated so far and still held by the costmap, by capture index, per mount.
  std::vector<std::map<long, model::PointCloud>> frames;
  std::vector<long> last_passed;  // newest frame given to the costmap, per mount
  PoseHistory history;
  costmap::Pose2 pose;
  std::size_t stop = 0;
  bool waiting = false;
  double wait_until = 0.0;
  costmap::VelocityCommand command;
  costmap::PlannedPath path;
  model::Vec2 goal;  // the local goal of the latest plan
  Recovery recovery;
  std::vector<model::PointCloud> clouds;  // the newest frame given to the costmap, per mount
};

ScenarioLoop::ScenarioLoop(const ScenarioDefinition& run_definition, const model::Rig& run_rig,
                           const ScenarioParams& run_params, const detail::Setup& run_setup,
                           const std::function<void(const ScenarioStep&)>& run_on_update)
    : scenario(run_definition),
      rig(run_rig),
      params(run_params),
      setup(run_setup),
      on_update(run_on_update),
      costmap(setup.costmap),
      band{params.ground_clearance, rig.body.height},
      static_scene(scenario.scene.moving.empty()),
      still_caster(still_mesh(scenario.scene)),
      still_checker(still_meshes(scenario.scene), band),
      steps_per_update(
          std::max(1, static_cast<int>(std::lround(params.control_rate / params.update_rate)))),
      dt(1.0 / params.control_rate),
      lookahead(std::min(params.goal_lookahead,
                         0.5 * std::min(setup.costmap.size_x, setup.costmap.size_y) -
                             2 * setup.costmap.resolution)),
      resolution(setup.costmap.resolution),
      dwa(params.dwa),
      leg_start(scenario.start.position),
      clocks(scenario.scene),
      frames(setup.mounts.size()),
      last_passed(setup.mounts.size(), -1),
      pose(scenario.start),
      goal(scenario.start.position),
      clouds(setup.mounts.size()) {
  for (std::size_t i = 0; i < setup.mounts.size(); ++i)
    streams.push_back(sim::noise_stream(params.seed, i));
  settings.add_noise = params.add_noise;
  settings.depth_matching = params.depth_matching;
  for (const detail::SimulatedMount& mount : setup.mounts) result.timings.push_back(mount.timing);
  result.route_size = scenario.route.size();
  recovery.closest = scenario.route.empty()
                         ? 0.0
                         : (scenario.route.front().position - scenario.start.position).norm();
  dwa.max_speed = params.follower.speed;
  dwa.max_angular_speed = params.follower.max_angular_speed;
}

bool ScenarioLoop::step(long k) {
  const double t = static_cast<double>(k) / params.control_rate;
  result.end_time = t;
  if (!judge(t)) return false;
  if (k % steps_per_update == 0) {
    // The command the costmap's motion condition sees is the one the robot is driving with.
    const bool velocity_command = !command.is_zero();
    update(t, sense(t), velocity_command);
    plan();
    publish(t, velocity_command);
  }
  if (!act(t)) return false;
  drive(k, t);
  return true;
}

ScenarioResult ScenarioLoop::finish() {
  result.trajectory.push_back({result.end_time, pose});
  double reached_distance = 0.0;
  double reached_seconds = 0.0;
  for (const StopOutcome& outcome : result.stops) {
    if (!outcome.reached) continue;
    reached_distance += outcome.leg_distance;
    reached_seconds += outcome.leg_seconds;
  }
  if (reached_seconds > 0.0) result.average_speed = reached_distance / reached_seconds;
  return std::move(result);
}

// Ground truth first: the pose reached by the last command, before the robot senses there.
// False when the run ends: a collision, a drop, the route done or the time up.
bool ScenarioLoop::judge(double t) {
  if (collided(t) || drove_off(t)) return false;
  pass_stops(t);
  if (stop >= scenario.route.size()) {
    result.reached_goal = true;
    return false;
  }
  return !(t > scenario.max_duration);
}

// Walkers count only while the robot drives: one who walks into a standing robot is not the
// robot's collision.
bool ScenarioLoop::collided(double t) {
  costmap::Clearance clearance = still_checker.clearance(pose.position, rig.body.radius);
  if (!static_scene) {
    std::vector<model::TriangleMesh> storage;
    const costmap::Clearance walker =
        costmap::FootprintCollisionChecker(moving_meshes_at(scenario.scene, clocks.now(), storage),
                                           band)
            .clearance(pose.position, rig.body.radius);
    if (command.linear != 0.0) {
      if (walker.distance < clearance.distance) clearance = walker;
    } else if (walker.distance < 0.0 && !touched_by_walker) {
      ++result.struck_while_standing;
    }
    touched_by_walker = walker.distance < 0.0;
  }
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
    return true;
  }
  return false;
}

bool ScenarioLoop::drove_off(double t) {
  const auto drop = std::find_if(scenario.drops.begin(), scenario.drops.end(),
                                 [&](const FloorDrop& d) { return d.contains(pose.position); });
  if (drop == scenario.drops.end()) return false;
  result.drove_off = true;
  result.drop_name = drop->name;
  result.drove_off_time = t;
  result.drove_off_speed = command.linear;
  return true;
}

// Stops: arrive, wait, leave.
void ScenarioLoop::pass_stops(double t) {
  if (waiting && t >= wait_until - 1e-9) {
    waiting = false;
    ++stop;
    start_leg(t);
  } else if (!waiting &&
             (pose.position - scenario.route[stop].position).norm() < params.goal_tolerance) {
    StopOutcome reached;
    reached.name = scenario.route[stop].name;
    reached.reached = true;
    reached.reached_time = t;
    reached.leg_distance = leg_distance;
    reached.leg_seconds = t - leg_start_time;
    result.stops.push_back(reached);
    ++result.goals_reached;
    if (scenario.route[stop].wait > 0.0) {
      waiting = true;
      wait_until = t + scenario.route[stop].wait;
    } else {
      ++stop;
      start_leg(t);
    }
  }
}

// Each mount's frames, captured at their own times, from where the robot was then, in the
// scene as it was then, arrived a latency later. Mount by mount in order: each draws its noise
// from its own stream.
std::vector<costmap::CloudObservation> ScenarioLoop::sense(double t) {
  std::vector<costmap::CloudObservation> observations;
  for (std::size_t i = 0; i < setup.mounts.size(); ++i) sense_mount(i, t, observations);
  return observations;
}

// Without persistence nav2's buffer holds the newest frame until the next one arrives, so it
// marks at every update; with persistence each frame goes to the costmap once, which keeps it
// for its persistence.
void ScenarioLoop::sense_mount(std::size_t i, double t,
                               std::vector<costmap::CloudObservation>& observations) {
  const detail::SimulatedMount& mount = setup.mounts[i];
  const bool keeps = mount.source.observation_persistence > 0.0;
  // With persistence the frames already passed on are not walked again.
  const std::vector<long> held = frames_held(mount.timing, t, mount.source.observation_persistence,
                                             keeps ? last_passed[i] : -1);
  std::map<long, model::PointCloud>& cache = frames[i];
  std::erase_if(cache, [&](const auto& frame) {
    return !std::binary_search(held.begin(), held.end(), frame.first);
  });
  for (const long index : held) {
    if (cache.count(index)) continue;
    cache[index] = cast_frame(i, index);
    ++result.frames_cast;
  }
  for (const auto& [index, cloud] : cache)
    observations.push_back({&cloud, model::Pose3::Identity(), mount.source});
  if (!cache.empty()) {
    clouds[i] = cache.rbegin()->second;
    last_passed[i] = cache.rbegin()->first;
  }
}

// Frame `index` of mount `i`, world frame, with the drops it shows marked when asked.
model::PointCloud ScenarioLoop::cast_frame(std::size_t i, long index) {
  const detail::SimulatedMount& mount = setup.mounts[i];
  const double captured = mount.timing.capture(index);
  std::optional<sim::RayCaster> moving_caster;
  if (!static_scene)
    moving_caster.emplace(moving_mesh_at(scenario.scene, clocks.at(captured)), still_caster);
  const sim::RayCaster& caster = static_scene ? still_caster : *moving_caster;
  const model::Pose3 T_world_sensor =
      detail::to_pose3(history.empty() ? pose : history.at(captured)) * mount.mount.T_robot_sensor;
  model::PointCloud frame = sim::simulate_frame(caster, mount.mode, mount.rays, T_world_sensor,
                                                settings, streams[i], mount.free_ranges);
  if (params.camera_radius_outlier && mount.mode.is_camera()) {
    model::RadiusOutlierParams stage = *params.camera_radius_outlier;
    stage.radius *= std::max(1, params.camera_decimation);
    frame = filters::radius_outlier_removal(frame, stage);
  }
  if (params.negative_obstacles) frame = with_negative_obstacles(frame, resolution, drop_marks);
  return frame;
}

void ScenarioLoop::update(double t, std::span<const costmap::CloudObservation> observations,
                          bool velocity_command) {
  const model::Pose3 T_world_robot = detail::to_pose3(pose);
  const Clock::time_point update_start = Clock::now();
  costmap.update(t, T_world_robot, observations, velocity_command);
  result.update_seconds.push_back(seconds_since(update_start));
}

// A local goal on the current leg and a global plan to it; none while waiting at a stop.
void ScenarioLoop::plan() {
  goal = pose.position;
  path = costmap::PlannedPath{};
  if (waiting) return;
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

void ScenarioLoop::publish(double t, bool velocity_command) {
  result.trajectory.push_back({t, pose});
  if (on_update) {
    ScenarioStep update_step;
    update_step.index = result.updates;
    update_step.time = t;
    update_step.pose = pose;
    update_step.velocity_command = velocity_command;
    update_step.waiting = waiting;
    update_step.costmap = &costmap;
    update_step.path = &path;
    update_step.goal = goal;
    update_step.clouds = clouds;
    update_step.object_clocks = clocks.now();
    on_update(update_step);
  }
  ++result.updates;
}

// The command, then paper 2's deadlock handling on it. False when the robot gave up.
bool ScenarioLoop::act(double t) {
  const bool blocked = choose_command(t);
  if (params.deadlock_recovery &&
      recover_if_stuck(recovery, blocked, waiting, t, stop, scenario.route[stop].position, pose,
                       costmap, params, result)) {
    return refuse_stop(t);
  }
  return true;
}

// Returns whether the robot is blocked: no plan, or no admissible velocity.
bool ScenarioLoop::choose_command(double t) {
  if (t < recovery.turning_until) {
    // Paper 2's recovery turn: on the spot, a full turn, sensing all the while.
    command = costmap::VelocityCommand{0.0, params.follower.max_angular_speed};
    result.recovery_seconds += dt;
    return false;
  }
  if (waiting) {
    command = costmap::VelocityCommand{};
    return false;
  }
  if (!path.found) {
    command = costmap::VelocityCommand{};
    return true;
  }
  if (params.local_planner == LocalPlanner::dwa) {
    const costmap::DwaResult chosen =
        costmap::plan_dwa(costmap.master(), pose, command, path.waypoints_world, goal, dt, dwa);
    if (!chosen.found) ++result.dwa_blocked_steps;
    command = chosen.command;
    return !chosen.found;
  }
  command = costmap::pursue(path.waypoints_world, pose, params.follower);
  return false;
}

// The current stop is unreachable: recorded as refused, then on to the next one, as a robot
// given a list of goals does, or the run ends. False when it ends.
bool ScenarioLoop::refuse_stop(double t) {
  StopOutcome refused;
  refused.name = scenario.route[stop].name;
  refused.refused = true;
  refused.reason = unreachable_reason(
      stop, refused.name, pose.position, scenario.route[stop].position, drop_marks, resolution,
      setup.costmap.inflation.inscribed_radius + resolution, params);
  refused.leg_distance = leg_distance;
  refused.leg_seconds = t - leg_start_time;
  result.stops.push_back(refused);
  if (!scenario.skip_unreachable || stop + 1 >= scenario.route.size()) {
    result.gave_up = true;
    result.gave_up_reason = refused.reason;
    return false;
  }
  ++stop;
  start_leg(t);
  command = costmap::VelocityCommand{};
  return true;
}

// The command of step `k` (at `t`) recorded, the objects' clocks moved on, the robot moved.
void ScenarioLoop::drive(long k, double t) {
  history.record(t, pose, command);
  clocks.record(t);
  clocks.advance(static_cast<double>(k + 1) / params.control_rate, dt, pose.position);
  const costmap::Pose2 next = costmap::integrate_unicycle(pose, command, dt);
  leg_distance += (next.position - pose.position).norm();
  result.distance += (next.position - pose.position).norm();
  pose = next;
}

void ScenarioLoop::start_leg(double t) {
  leg_start = pose.position;
  leg_start_time = t;
  leg_distance = 0.0;
}

}  // namespace

void apply_scenario_settings(const ScenarioDefinition& scenario, ScenarioParams& params) {
  if (scenario.min_obstacle_height)
    params.source.min_obstacle_height = *scenario.min_obstacle_height;
  if (scenario.camera_decimation) params.camera_decimation = *scenario.camera_decimation;
  if (scenario.lidar_decimation) params.lidar_decimation = *scenario.lidar_decimation;
  if (scenario.negative_obstacles) params.negative_obstacles = *scenario.negative_obstacles;
}

TimeSummary summarize_times(const std::vector<double>& seconds) {
  if (seconds.empty()) return {};
  return {model::median(seconds), model::percentile(seconds, 0.99)};
}

ScenarioResult run_scenario(const ScenarioDefinition& scenario, const model::Rig& rig,
                            const model::SensorLibrary& library, const ScenarioParams& params,
                            const std::function<void(const ScenarioStep&)>& on_update) {
  check_scenario_inputs(rig, library, params);
  const detail::Setup setup = detail::make_setup(rig, library, params);
  ScenarioLoop loop(scenario, rig, params, setup, on_update);
  long k = 0;
  while (loop.step(k)) ++k;
  return loop.finish();
}

}  // namespace rigdesign::scenarios
