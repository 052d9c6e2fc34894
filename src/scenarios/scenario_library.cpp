// The named robot-in-the-loop scenarios (issue 6 items 2 and 4).
#include "rigdesign/scenarios/scenario_library.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/sim/mesh_primitives.hpp"
#include "rigdesign/sim/office_goals_scene.hpp"
#include "rigdesign/sim/scene_library.hpp"

namespace rigdesign::scenarios {
namespace {

// Wall following (paper 1 Fig. 12): the robot starts at the scene's start pose, 0.6 m from
// the wall, and drives 6 m along it, past the table whose foam top overhangs into its lane
// (x 3.0 to 4.2 m). 6 m leaves the robot 1.8 m past the foam's end.
constexpr double kWallFollowingGoalX = 6.0;
constexpr double kWallFollowingMaxDuration = 40.0;  // [s] 15 s of driving at 0.4 m/s, detours

// Stationary (the motion condition): a cart stands between the robot's lane and the wall
// until it is taken away at kCartGoneAt; the robot waits at its start until kWaitUntil and
// then drives the wall-following route. The cart's cells leave the obstacle layer (the lidar
// sees the wall behind them) but the Hit Layer keeps them while the robot stands still.
const model::Vec3 kCartLow(1.3, 0.05, 0.0);
const model::Vec3 kCartHigh(1.7, 0.45, 0.7);
constexpr double kCartGoneAt = 2.9;  // [s] between the updates at 2.8 s and 3.0 s (5 Hz)
constexpr double kWaitUntil = 12.0;  // [s] more than d_duration (10 s) after the cart left
constexpr double kStationaryMaxDuration = 45.0;

costmap::Pose2 start_of(const model::Scene& scene) {
  costmap::Pose2 start;
  start.position = scene.T_world_robot.translation().head<2>();
  const model::Vec3 forward = scene.T_world_robot.linear().col(0);
  start.yaw = std::atan2(forward.y(), forward.x());
  return start;
}

// [m] between the robot's side and the followed wall: paper 1's UR Cleaner (r = 0.45 m)
// drives 0.6 m from the wall's face, and every robot keeps the same gap, so the foam reaches
// equally far into its swept band.
constexpr double kSideToWall = 0.15;

// The face of the scene's followed wall (its lowest y): the lane is placed from it.
double wall_face_y(const model::Scene& scene) {
  for (const model::SceneObject& object : scene.objects) {
    if (object.name != "wall") continue;
    double face = std::numeric_limits<double>::infinity();
    for (const model::Vec3& v : object.mesh.vertices) face = std::min(face, v.y());
    return face;
  }
  throw std::logic_error("the wall-following scene has no wall");
}

ScenarioDefinition wall_following(std::uint64_t seed, double body_radius) {
  ScenarioDefinition scenario;
  scenario.name = "wall_following";
  scenario.description =
      "drive 6 m along the wall past a table whose foam top (0.33-0.39 m) overhangs the lane";
  scenario.scene = sim::make_scene("wall_following", seed);
  scenario.start = start_of(scenario.scene);
  scenario.start.position.y() = wall_face_y(scenario.scene) - body_radius - kSideToWall;
  scenario.route = {
      {model::Vec2(kWallFollowingGoalX, scenario.start.position.y()), 0.0, "end of the wall"}};
  scenario.max_duration = kWallFollowingMaxDuration;
  return scenario;
}

ScenarioDefinition stationary(std::uint64_t seed, double body_radius) {
  ScenarioDefinition scenario = wall_following(seed, body_radius);
  scenario.name = "stationary";
  scenario.description = "wait 12 s while a cart 1.3 m ahead is taken away at 2.9 s, then drive";
  model::MovingObject cart;
  cart.name = "cart";
  // Beside the lane, as for the UR Cleaner (lane y = 0), short of the wall for any robot.
  const double lane = scenario.start.position.y();
  const double wall = wall_face_y(scenario.scene);
  cart.mesh =
      sim::aligned_box({kCartLow.x(), lane + kCartLow.y(), kCartLow.z()},
                       {kCartHigh.x(), std::min(lane + kCartHigh.y(), wall - 0.05), kCartHigh.z()});
  // Taken away: moved far below the floor, where no ray and no body reaches.
  cart.T_world_object = [](double t) {
    return t < kCartGoneAt ? model::Pose3::Identity()
                           : model::Pose3(Eigen::Translation3d(0.0, 0.0, -100.0));
  };
  scenario.scene.moving.push_back(std::move(cart));
  scenario.route.insert(scenario.route.begin(),
                        RouteStop{scenario.start.position, kWaitUntil, "start, waiting"});
  scenario.max_duration = kStationaryMaxDuration;
  return scenario;
}

// Office goals: seven goals; 0.3 m/s over about 27 m of legs is 90 s, so 300 s leaves room for
// detours, people crossing and the recoveries of goals found unreachable.
constexpr double kOfficeGoalsMaxDuration = 300.0;
// [m] the door gap over the robot's width: 5 cm of margin passes, 20 cm does not (5 cm cells).
constexpr double kDoorGapOverWidth = 0.25;
// [m] the lowest height that marks in the office: below the chairs' star bars (0.05-0.07 m)
// and casters (0 to 0.05 m) the robot's body rides over (ground clearance 0.02 m). The
// Kinect's floor noise at these grazing angles is millimetres, far below it.
constexpr double kOfficeMinObstacleHeight = 0.04;

ScenarioDefinition office_goals(std::uint64_t seed, double body_radius) {
  sim::OfficeGoalsLayout layout = sim::make_office_goals_scene(seed, office_door_gap(body_radius));
  ScenarioDefinition scenario;
  scenario.name = "office_goals";
  scenario.description =
      "seven goals in an office: between chairs, through a door ajar to " +
      model::format_number(layout.door_gap) +
      " m, past two people walking, and last a landing beyond a stairwell (unreachable)";
  scenario.scene = std::move(layout.scene);
  scenario.start = start_of(scenario.scene);
  for (const sim::NamedPlace& goal : layout.goals)
    scenario.route.push_back({goal.position, 0.0, goal.name});
  for (const sim::FloorOpening& opening : layout.openings)
    scenario.drops.push_back({opening.name, opening.area.low, opening.area.high});
  scenario.max_duration = kOfficeGoalsMaxDuration;
  scenario.skip_unreachable = true;
  scenario.min_obstacle_height = kOfficeMinObstacleHeight;
  // Every lidar ray: a 4 cm desk leg spans 0.76 deg at 3 m, a stride of 4 LMS100 rays 2 deg.
  // Cameras keep the default stride of 8 pixels (0.71 deg on a Kinect: 3.7 cm at 3 m), so a
  // leg is hit within 3 m; --full-rays casts all.
  scenario.lidar_decimation = 1;
  // Paper 2's pipeline marks drops (its Kinect recognised the stairs every time).
  scenario.negative_obstacles = true;
  return scenario;
}

}  // namespace

double office_door_gap(double body_radius) {
  return std::min(2.0 * body_radius + kDoorGapOverWidth, sim::kOfficeDoorMaxGap);
}

const std::vector<std::string>& costmap_scenario_names() {
  static const std::vector<std::string> names = {"wall_following", "stationary", "office_goals"};
  return names;
}

ScenarioDefinition make_costmap_scenario(const std::string& name, std::uint64_t seed,
                                         double body_radius) {
  if (name == "wall_following") return wall_following(seed, body_radius);
  if (name == "stationary") return stationary(seed, body_radius);
  if (name == "office_goals") return office_goals(seed, body_radius);
  throw std::invalid_argument("unknown costmap scenario '" + name + "'");
}

costmap::CostmapParams scenario_costmap_defaults() {
  costmap::CostmapParams params;
  params.size_x = 6.0;
  params.size_y = 6.0;
  params.layer = costmap::ObstacleLayerKind::obstacle;
  return params;
}

costmap::ObservationSource scenario_source_defaults() {
  costmap::ObservationSource source;
  source.min_obstacle_height = 0.10;
  return source;
}

}  // namespace rigdesign::scenarios
