#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/footprint_collision.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"
#include "support/box_mesh.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

struct UrCleaner {
  model::Rig rig = io::load_rig(source_path("rigs/ur_cleaner.yaml"));
  model::SensorLibrary library = io::load_sensor_library(io::locate_sensor_library(rig, ""));
};

const UrCleaner& ur_cleaner() {
  static const UrCleaner loaded;
  return loaded;
}

scenarios::ScenarioResult run(
    const std::string& name, costmap::ObstacleLayerKind layer, bool hit_layer,
    const std::function<void(const scenarios::ScenarioStep&)>& on_update = {},
    double d_threshold = costmap::HitLayerParams{}.d_threshold, bool idealised_sensing = false) {
  scenarios::ScenarioParams params;
  if (idealised_sensing) {
    // Every sensor captures at t = 0 and at its own rate (a multiple of 5 Hz on the UR
    // Cleaner, or faster), and its frame reaches the costmap at once: each update sees the
    // scene as it is then, so the counts below follow from the update times alone.
    params.frame_phases.assign(ur_cleaner().rig.mounts.size(), 0.0);
    params.model_latency = false;
  }
  params.costmap.layer = layer;
  params.costmap.use_hit_layer = hit_layer;
  params.costmap.hit.d_threshold = d_threshold;
  return scenarios::run_scenario(
      scenarios::make_costmap_scenario(name, 1, ur_cleaner().rig.body.radius), ur_cleaner().rig,
      ur_cleaner().library, params, on_update);
}

// Largest Hit Layer count over the cells whose centres lie in the stationary scenario's
// cart footprint (x 1.3-1.7 m, y 0.05-0.45 m), and whether the obstacle grid marks any.
struct CartCells {
  int max_count = 0;
  bool observed = false;
};
CartCells cart_cells(const costmap::Costmap& costmap) {
  CartCells cells;
  const costmap::GridWindow& window = costmap.hit_layer().counts().window();
  for (int y = 0; y < window.height; ++y) {
    for (int x = 0; x < window.width; ++x) {
      const model::Vec2 c = window.centre_of(x, y);
      if (c.x() < 1.3 || c.x() > 1.7 || c.y() < 0.05 || c.y() > 0.45) continue;
      cells.max_count = std::max<int>(cells.max_count, costmap.hit_layer().counts().at(x, y));
      cells.observed = cells.observed || costmap.obstacle_grid().at(x, y) == costmap::cost::kLethal;
    }
  }
  return cells;
}

}  // namespace

TEST_CASE("collision check: clearance to a hand-placed box within the body's height band",
          "[scenario]") {
  const model::TriangleMesh block = test::box_mesh({1.0, -0.2, 0.0}, {1.4, 0.2, 0.5});
  const model::TriangleMesh shelf =
      test::box_mesh({-1.4, -0.2, 1.2}, {-1.0, 0.2, 1.5});  // above the 1 m body
  const model::TriangleMesh floor =
      test::box_mesh({-5, -5, -0.1}, {5, 5, 0.0});  // top face at z = 0
  const costmap::FootprintCollisionChecker checker(
      {{"block", &block}, {"shelf", &shelf}, {"floor", &floor}}, costmap::HeightBand{0.02, 1.0});
  // Axis at the origin: the block's near face is 1.0 m away, the body's radius 0.45 m.
  costmap::Clearance c = checker.clearance({0.0, 0.0}, 0.45);
  CHECK(c.distance == Approx(1.0 - 0.45));
  CHECK(c.object == "block");
  // Nearest point is the block's corner (1.0, 0.2): sqrt(0.5^2 + 0.3^2) - 0.45.
  CHECK(checker.clearance({0.5, 0.5}, 0.45).distance == Approx(std::sqrt(0.34) - 0.45));
  // Overlap: 0.3 m from the face, 0.15 m into the body.
  CHECK(checker.clearance({0.7, 0.0}, 0.45).distance == Approx(-0.15));
  // Under the shelf: it is above the body and the floor below it, so nothing but the block
  // 2.0 m away (from x = -1.0 to the block's face at 1.0) counts.
  CHECK(checker.clearance({-1.0, 0.0}, 0.45).distance == Approx(2.0 - 0.45));
  // An overhang inside the band counts even with nothing under it.
  const model::TriangleMesh foam = test::box_mesh({0.0, 0.15, 0.37}, {1.2, 0.6, 0.45});
  const costmap::FootprintCollisionChecker overhang({{"foam", &foam}},
                                                    costmap::HeightBand{0.02, 1.0});
  CHECK(overhang.clearance({0.6, 0.0}, 0.45).distance == Approx(0.15 - 0.45));
  CHECK(overhang.clearance({0.6, -0.4}, 0.45).distance == Approx(0.55 - 0.45));
  const costmap::FootprintCollisionChecker low_body({{"foam", &foam}},
                                                    costmap::HeightBand{0.02, 0.3});
  CHECK(std::isinf(low_body.clearance({0.6, 0.0}, 0.45).distance));
}

TEST_CASE("path follower: pure pursuit command and the unicycle's exact arc", "[scenario]") {
  costmap::FollowerParams params;  // 0.4 m/s, 1 rad/s, lookahead 0.6 m
  // Straight ahead: full speed, no turn.
  costmap::VelocityCommand straight =
      costmap::pursue({{0.0, 0.0}, {0.3, 0.0}, {0.6, 0.0}, {0.9, 0.0}}, costmap::Pose2{}, params);
  CHECK(straight.linear == Approx(0.4));
  CHECK(straight.angular == Approx(0.0).margin(1e-12));
  // Target (0.6, 0.6): 45 degrees left at 0.6 sqrt 2 m, curvature 2 sin 45 / (0.6 sqrt 2) = 5/3.
  costmap::VelocityCommand left =
      costmap::pursue({{0.0, 0.0}, {0.6, 0.6}}, costmap::Pose2{}, params);
  CHECK(left.linear == Approx(0.4));
  CHECK(left.angular == Approx(0.4 * 5.0 / 3.0));
  // Behind the robot: turn on the spot towards it.
  costmap::VelocityCommand behind =
      costmap::pursue({{0.0, 0.0}, {-1.0, 0.1}}, costmap::Pose2{}, params);
  CHECK(behind.linear == 0.0);
  CHECK(behind.angular == Approx(1.0));
  // A quarter circle of radius 1: from the origin facing +x to (1, 1) facing +y.
  const costmap::Pose2 end =
      costmap::integrate_unicycle(costmap::Pose2{}, {1.0, 1.0}, std::acos(-1.0) / 2);
  CHECK(end.position.x() == Approx(1.0));
  CHECK(end.position.y() == Approx(1.0));
  CHECK(end.yaw == Approx(std::acos(-1.0) / 2));
}

TEST_CASE("path follower reaches the goal on an empty floor", "[scenario]") {
  scenarios::ScenarioDefinition scenario;
  scenario.name = "empty";
  scenario.scene.objects.push_back({"floor", test::box_mesh({-5, -5, -0.1}, {5, 5, 0.0})});
  scenario.route = {{model::Vec2(3.0, 1.0), 0.0, "goal"}};
  scenario.max_duration = 20.0;
  scenarios::ScenarioParams params;
  const scenarios::ScenarioResult result =
      scenarios::run_scenario(scenario, ur_cleaner().rig, ur_cleaner().library, params);
  CHECK(result.reached_goal);
  CHECK_FALSE(result.collided);
  CHECK(std::isinf(result.min_clearance));  // the floor is below the body's band
  CHECK(result.planner_failures == 0);
  // sqrt(10) = 3.16 m at 0.4 m/s takes 7.9 s at least; the turn at the start costs little.
  CHECK(result.end_time >= std::sqrt(10.0) / 0.4 - 0.15 / 0.4);
  CHECK(result.end_time <= std::sqrt(10.0) / 0.4 + 2.0);
  CHECK((result.trajectory.back().pose.position - model::Vec2(3.0, 1.0)).norm() <
        params.goal_tolerance);
}

TEST_CASE("paper 1 Fig. 12: without the Hit Layer the robot drives into the foam, with it not",
          "[scenario]") {
  const scenarios::ScenarioResult forgetting =
      run("wall_following", costmap::ObstacleLayerKind::obstacle, false);
  CHECK(forgetting.collided);
  CHECK(forgetting.collision_object == "foam");
  // Contact is found within one control step: at most 0.4 m/s x 0.05 s = 2 cm deep.
  CHECK(forgetting.min_clearance < 0.0);
  CHECK(forgetting.min_clearance >= -0.4 / 20.0);
  // The foam spans x 3.0-4.2 m; the body (r 0.45) meets it only with its axis past 2.55 m.
  CHECK(forgetting.collision_position.x() > 3.0 - 0.45);
  CHECK(forgetting.collision_position.x() < 4.2 + 0.45);

  const scenarios::ScenarioResult remembering =
      run("wall_following", costmap::ObstacleLayerKind::obstacle, true);
  CHECK_FALSE(remembering.collided);
  CHECK(remembering.reached_goal);
  CHECK(remembering.min_clearance > 0.0);
  // At the start the wall is 0.6 m from the axis: 0.15 m clearance, an upper bound.
  CHECK(remembering.min_clearance <= 0.6 - 0.45 + 1e-9);

  // Paper 2's voxel layer keeps the foam without help: the lidar's rays pass above its voxels.
  const scenarios::ScenarioResult voxels =
      run("wall_following", costmap::ObstacleLayerKind::voxel, false);
  CHECK_FALSE(voxels.collided);
  CHECK(voxels.reached_goal);
}

TEST_CASE("stationary: the motion condition keeps the cart's cells while the robot waits",
          "[scenario]") {
  // The cart stands in view for the updates at t = 0, 0.2, ..., 2.8 s (15 updates, 5 Hz) and
  // is gone from 2.9 s: its cells reach 15 x hit = 45 (paper 1, eq. 8).
  constexpr int kSeen = 15 * 3;
  int at_wait_end = -1;
  bool observed_at_wait_end = true;
  int moving_updates = 0;
  int after_ten_moving = -1;
  const double paper_threshold = costmap::HitLayerParams{}.d_threshold;
  run(
      "stationary", costmap::ObstacleLayerKind::obstacle, true,
      [&](const scenarios::ScenarioStep& step) {
        const CartCells cells = cart_cells(*step.costmap);
        if (std::abs(step.time - 2.8) < 1e-9) CHECK(cells.max_count == kSeen);
        if (std::abs(step.time - 11.8) < 1e-9) {
          at_wait_end = cells.max_count;
          observed_at_wait_end = cells.observed;
        }
        if (step.time > 12.0 - 1e-9 && step.velocity_command && ++moving_updates == 10) {
          after_ten_moving = cells.max_count;
        }
      },
      paper_threshold, true);
  // Standing still since t = 0, the robot never decrements (eq. 9 skipped): 45 after 9 s of
  // the obstacle layer seeing free space there.
  CHECK(at_wait_end == kSeen);
  CHECK_FALSE(observed_at_wait_end);
  // Driving, each update takes one: 45 - 10.
  CHECK(after_ten_moving == kSeen - 10);

  // With d_threshold = 0 the robot always counts as moving: the updates from 3.0 s to 11.8 s
  // (45 of them) take the count from 45 to 0 while it waits.
  int dropped = -1;
  run(
      "stationary", costmap::ObstacleLayerKind::obstacle, true,
      [&](const scenarios::ScenarioStep& step) {
        if (std::abs(step.time - 5.0) < 1e-9)
          CHECK(cart_cells(*step.costmap).max_count == kSeen - 11);
        if (std::abs(step.time - 11.8) < 1e-9) dropped = cart_cells(*step.costmap).max_count;
      },
      0.0, true);
  CHECK(dropped == 0);
}

TEST_CASE("scenario inputs: a rig whose sensors cannot mark is refused", "[scenario]") {
  model::Rig rig = ur_cleaner().rig;
  scenarios::ScenarioParams params;
  // Only the Azure Kinect, looking straight up from 1.5 m: its rays (65 degrees wide around
  // the vertical) all climb, so none reaches the band 0.1-1.0 m.
  rig.mounts.resize(1);
  rig.mounts.front().T_robot_sensor = model::Pose3(Eigen::Translation3d(0.0, 0.0, 1.5)) *
                                      Eigen::AngleAxisd(-std::acos(-1.0) / 2, model::Vec3::UnitY());
  try {
    scenarios::check_scenario_inputs(rig, ur_cleaner().library, params);
    FAIL("expected an InputError");
  } catch (const model::InputError& error) {
    REQUIRE(error.diagnostics().size() == 1);
    CHECK(error.diagnostics().front().field == "mounts");
    CHECK(error.diagnostics().front().where.file == rig.where.file);
  }
  CHECK_THROWS_AS(scenarios::make_costmap_scenario("moon", 1, 0.45), std::invalid_argument);
  const scenarios::TimeSummary times = scenarios::summarize_times({0.004, 0.001, 0.003, 0.002});
  CHECK(times.median == Approx(0.0025));
  CHECK(times.p99 == Approx(0.004));
}

TEST_CASE("any robot: the wall-following lane keeps the robot's side 0.15 m from the wall",
          "[scenario]") {
  // The wall's face stands at y = 0.6 m (sim/wall_following_scene.cpp). A robot of radius r
  // starts at y = 0.6 - r - 0.15, so at the start its body is 0.15 m from the wall whatever r
  // is: the UR Cleaner (0.45 m) at y = 0 as in paper 1, a Husky-sized 0.57 m at y = -0.12
  // (before, every robot started at y = 0: 0.03 m from the wall).
  for (const double radius : {0.2, 0.45, 0.57}) {
    INFO("radius " << radius);
    const scenarios::ScenarioDefinition scenario =
        scenarios::make_costmap_scenario("wall_following", 1, radius);
    CHECK(scenario.start.position.y() == Approx(0.6 - radius - 0.15).margin(1e-12));
    CHECK(scenario.route.back().position.y() == scenario.start.position.y());
    std::vector<costmap::NamedMesh> meshes;
    for (const model::SceneObject& object : scenario.scene.objects)
      meshes.push_back({object.name, &object.mesh});
    const costmap::FootprintCollisionChecker checker(meshes, costmap::HeightBand{0.02, 1.0});
    const costmap::Clearance at_start = checker.clearance(scenario.start.position, radius);
    CHECK(at_start.distance == Approx(0.15).margin(1e-9));
    CHECK(at_start.object == "wall");
  }
}
