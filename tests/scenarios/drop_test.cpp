// Issue 35 item 4: stairs and cliffs in the loop. A corridor whose floor has a 1.5 m wide
// opening across its whole width, and a goal beyond it. A rig whose camera sees the floor
// ahead marks the drop (paper 2's negative obstacles) and refuses the goal naming it; a rig
// with only a horizontal lidar drives off the edge. Expected values are derived from the
// geometry below by hand.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/scenarios/floor_ahead.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"
#include "rigdesign/sim/mesh_primitives.hpp"
#include "support/box_mesh.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

// Camera: 60 x 40 deg, 48 pixel rows, 0.3-5 m, 0.6 m up on the front of the 0.25 m body (a
// sensor inside the body sees nothing: issue 52), pitched 30 deg down: its top edge points
// 10 deg below the horizon.
constexpr double kCameraX = 0.26;
constexpr double kCameraZ = 0.6;
constexpr double kPitch = 30.0;         // [deg]
constexpr double kHalfVertical = 20.0;  // [deg]

model::SensorLibrary library() {
  model::SensorMode camera;
  camera.id = "depth";
  camera.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(60), model::deg_to_rad(40)));
  camera.angular_resolution_h = camera.fov.horizontal() / 64;
  camera.angular_resolution_v = camera.fov.vertical() / 48;
  camera.min_range = 0.3;
  camera.max_range = 5.0;
  camera.frequency = 10.0;
  camera.points_per_frame = 64 * 48;
  model::SensorMode lidar;
  lidar.id = "scan";
  lidar.fov = model::FieldOfView(
      model::band_fov(2 * std::numbers::pi, model::deg_to_rad(-1), model::deg_to_rad(1)));
  lidar.angular_resolution_h = model::deg_to_rad(1.0);
  lidar.angular_resolution_v = model::deg_to_rad(2.0);
  lidar.min_range = 0.1;
  lidar.max_range = 10.0;
  lidar.frequency = 10.0;
  lidar.points_per_frame = 360;
  model::SensorLibrary library;
  model::Sensor camera_sensor;
  camera_sensor.id = "camera";
  camera_sensor.modes.push_back(camera);
  model::Sensor lidar_sensor;
  lidar_sensor.id = "lidar";
  lidar_sensor.technology = model::Technology::lidar_2d;
  lidar_sensor.modes.push_back(lidar);
  library.sensors = {camera_sensor, lidar_sensor};
  return library;
}

model::Mount mount(const std::string& id, const std::string& mode, const model::Vec3& xyz,
                   double pitch_deg) {
  model::Mount m;
  m.id = id;
  m.sensor_id = id;
  m.mode_id = mode;
  m.T_robot_sensor = model::pose_from_xyz_rpy(xyz, {0, model::deg_to_rad(pitch_deg), 0});
  return m;
}

model::Rig rig(bool with_camera) {
  model::Rig rig;
  rig.body.radius = 0.25;
  rig.body.height = 0.7;
  rig.distance_of_interest = 3.0;
  if (with_camera) rig.mounts.push_back(mount("camera", "depth", {kCameraX, 0, kCameraZ}, kPitch));
  rig.mounts.push_back(mount("lidar", "scan", {0.26, 0, 0.2}, 0.0));
  return rig;
}

// Corridor x -1..6 m between walls at y = +-1 m; the floor open for x 2.0..3.5 across the
// whole width, over a 1 m deep pit lined with walls.
constexpr double kEdge = 2.0;
constexpr double kFarEdge = 3.5;

scenarios::ScenarioDefinition corridor_with_drop() {
  scenarios::ScenarioDefinition scenario;
  scenario.name = "drop";
  const auto add = [&](const std::string& name, model::TriangleMesh mesh) {
    scenario.scene.objects.push_back({name, std::move(mesh)});
  };
  add("floor", sim::floor_with_openings({{-1, -1}, {6, 1}}, {{{kEdge, -1}, {kFarEdge, 1}}}, 0.0));
  add("wall_left", test::box_mesh({-1, 1, -1}, {6, 1.1, 1}));
  add("wall_right", test::box_mesh({-1, -1.1, -1}, {6, -1, 1}));
  add("pit_near", test::box_mesh({kEdge - 0.1, -1, -1}, {kEdge, 1, 0}));
  add("pit_far", test::box_mesh({kFarEdge, -1, -1}, {kFarEdge + 0.1, 1, 0}));
  add("pit_bottom", test::box_mesh({kEdge, -1, -1.1}, {kFarEdge, 1, -1}));
  scenario.route = {{{5.0, 0.0}, 0.0, "beyond the drop"}};
  scenario.drops = {{"pit", {kEdge, -1}, {kFarEdge, 1}}};
  scenario.max_duration = 60.0;
  return scenario;
}

scenarios::ScenarioParams params() {
  scenarios::ScenarioParams p;
  p.add_noise = false;
  p.source.min_obstacle_height = 0.04;
  p.negative_obstacles = true;
  return p;
}

}  // namespace

TEST_CASE("a rig that sees the floor ahead refuses a goal beyond a drop, naming it", "[scenario]") {
  const scenarios::ScenarioResult result =
      scenarios::run_scenario(corridor_with_drop(), rig(true), library(), params());
  INFO("end " << result.end_time << " recoveries " << result.recoveries << " failures "
              << result.planner_failures << " x " << result.trajectory.back().pose.position.x()
              << " y " << result.trajectory.back().pose.position.y());
  CHECK_FALSE(result.collided);
  CHECK_FALSE(result.drove_off);
  CHECK(result.gave_up);
  REQUIRE(result.stops.size() == 1);
  CHECK(result.stops[0].refused);
  const std::string& reason = result.stops[0].reason;
  CHECK(reason.find("a drop (stairs or a hole)") != std::string::npos);
  // The marks lie where rays into the pit cross z = 0: over the opening, so from its near edge
  // (2.0 m) on; the nearest is within a cell or two of the edge.
  const std::size_t at = reason.find("marked at (");
  REQUIRE(at != std::string::npos);
  const double x = std::stod(reason.substr(at + 11));
  CHECK(x >= kEdge);
  CHECK(x <= kEdge + 0.15);
  // The robot stopped short of the edge: its body never passed over it.
  for (const scenarios::TrajectorySample& sample : result.trajectory)
    CHECK(sample.pose.position.x() < kEdge);
}

TEST_CASE("a rig with only a horizontal lidar drives off the drop", "[scenario]") {
  const scenarios::ScenarioResult result =
      scenarios::run_scenario(corridor_with_drop(), rig(false), library(), params());
  CHECK_FALSE(result.collided);
  REQUIRE(result.drove_off);
  CHECK(result.drop_name == "pit");
  // Straight down the corridor at the follower's 0.4 m/s from x = 0: the centre reaches the
  // edge at 2.0 / 0.4 = 5 s, plus the first plan's wait (at most one 0.2 s update).
  CHECK(result.drove_off_time >= 5.0 - 1e-9);
  CHECK(result.drove_off_time <= 5.0 + 0.2 + 0.05 + 1e-9);
  CHECK_THAT(result.drove_off_speed, WithinAbs(0.4, 1e-12));
}

TEST_CASE("floor ahead: a camera pitched down sees the floor to where its top edge meets it",
          "[scenario]") {
  const model::Rig with_camera = rig(true);
  const model::SensorLibrary sensors = library();
  scenarios::MountTiming timing;
  timing.period = 0.1;
  timing.driver = 0.02;
  const std::vector<scenarios::MountTiming> timings = {timing, timing};
  const scenarios::FloorAhead floor =
      scenarios::floor_ahead(with_camera, sensors, timings, 0.2, 0.05, 2.5);
  CHECK(floor.mount == "camera");
  // The top pixel row lies within one row (40/48 deg) below the FOV's edge at 10 deg down.
  const double edge = model::deg_to_rad(kPitch - kHalfVertical);
  const double row = model::deg_to_rad(40.0 / 48.0);
  CHECK(floor.distance <= kCameraX + kCameraZ / std::tan(edge) + 1e-9);
  CHECK(floor.distance >= kCameraX + kCameraZ / std::tan(edge + row) - 1e-9);
  CHECK_THAT(floor.reaction, WithinAbs(0.1 + 0.02 + 0.2 + 0.05, 1e-12));
  // The speed satisfies its definition: reaction distance plus braking distance fill the
  // distance from the body's front to the edge seen.
  const double v = floor.stoppable_speed;
  CHECK_THAT(v * floor.reaction + v * v / (2 * 2.5),
             WithinAbs(floor.distance - with_camera.body.radius, 1e-9));

  const scenarios::FloorAhead none =
      scenarios::floor_ahead(rig(false), sensors, {timing}, 0.2, 0.05, 2.5);
  CHECK(none.mount.empty());
  CHECK(none.stoppable_speed == 0.0);
}
