// Issue 35 item 2: paper 2's deadlock handling. A goal walled in on every side: the robot
// drives up to the wall, finds no way on, clears the costmap beyond 0.5 m and turns a full
// turn, then clears it all and turns again, then gives up with a message, never touching
// the wall.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"
#include "support/box_mesh.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

TEST_CASE("deadlock: a walled-in goal gets two recoveries, then the run gives up", "[scenario]") {
  model::SensorMode mode;
  mode.id = "m";
  mode.fov = model::FieldOfView(
      model::band_fov(2 * std::numbers::pi, model::deg_to_rad(-15), model::deg_to_rad(15)));
  mode.min_range = 0.1;
  mode.max_range = 10.0;
  mode.frequency = 10.0;
  mode.angular_resolution_h = model::deg_to_rad(1.0);
  mode.angular_resolution_v = model::deg_to_rad(2.0);
  mode.points_per_frame = 360 * 16;
  model::SensorLibrary library;
  model::Sensor sensor;
  sensor.id = "lidar";
  sensor.modes.push_back(mode);
  library.sensors.push_back(sensor);
  model::Rig rig;
  rig.body.radius = 0.2;
  rig.body.height = 0.5;
  rig.distance_of_interest = 3.0;
  model::Mount mount;
  mount.id = "lidar";
  mount.sensor_id = "lidar";
  mount.mode_id = "m";
  // On the body's top (a sensor inside the body sees nothing: issue 52); its lowest ring
  // meets the top.
  mount.T_robot_sensor = model::pose_from_xyz_rpy({0.0, 0.0, 0.55}, {0, 0, 0});
  rig.mounts.push_back(mount);

  // Four walls 5 cm thick, 1 m high, round the goal (2, 0): inside 0.5 x 0.5 m.
  scenarios::ScenarioDefinition scenario;
  scenario.name = "walled_goal";
  const auto wall = [&](model::Vec3 low, model::Vec3 high) {
    scenario.scene.objects.push_back({"wall", test::box_mesh(low, high)});
  };
  wall({1.70, -0.30, 0.0}, {1.75, 0.30, 1.0});
  wall({2.25, -0.30, 0.0}, {2.30, 0.30, 1.0});
  wall({1.70, -0.30, 0.0}, {2.30, -0.25, 1.0});
  wall({1.70, 0.25, 0.0}, {2.30, 0.30, 1.0});
  scenario.route = {{{2.0, 0.0}, 0.0, "walled-in goal"}};
  scenario.max_duration = 90.0;

  scenarios::ScenarioParams params;
  params.add_noise = false;
  for (const scenarios::LocalPlanner planner :
       {scenarios::LocalPlanner::pure_pursuit, scenarios::LocalPlanner::dwa}) {
    params.local_planner = planner;
    INFO((planner == scenarios::LocalPlanner::dwa ? "dwa" : "pure pursuit"));
    const scenarios::ScenarioResult result =
        scenarios::run_scenario(scenario, rig, library, params);
    CHECK_FALSE(result.collided);
    CHECK_FALSE(result.reached_goal);
    CHECK(result.gave_up);
    CHECK(result.recoveries == 2);
    CHECK(result.gave_up_reason.find("unreachable") != std::string::npos);
    // Two full turns at the follower's 1 rad/s, each counted in 0.05 s control steps.
    CHECK_THAT(result.recovery_seconds, WithinAbs(2 * 2 * std::numbers::pi, 2 * 0.05 + 1e-9));
    CHECK(result.end_time < scenario.max_duration);
  }
}
