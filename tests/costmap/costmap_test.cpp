#include "rigdesign/costmap/costmap.hpp"

#include <catch2/catch.hpp>
#include <numbers>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/model/input_error.hpp"

using namespace rigdesign;

namespace {

const model::Diagnostic& only_finding(const costmap::CostmapParams& params,
                                      const model::SourceLocation& where,
                                      const std::string& prefix = {}) {
  static std::vector<model::Diagnostic> kept;
  try {
    costmap::check_costmap_params(params, where, prefix);
  } catch (const model::InputError& error) {
    kept = error.diagnostics();
    REQUIRE(kept.size() == 1);
    return kept.front();
  }
  FAIL("expected an InputError");
  return kept.front();
}

model::PointCloud cloud_from(const model::Point3f& origin, std::vector<model::Point3f> points) {
  model::PointCloud cloud;
  cloud.origin = origin;
  cloud.points = std::move(points);
  return cloud;
}

model::Pose3 at_x(double x) {
  return model::Pose3(Eigen::Translation3d(x, 0.0, 0.0));
}

}  // namespace

TEST_CASE("costmap parameters: bad resolution and a window smaller than the footprint",
          "[costmap]") {
  costmap::CostmapParams params;
  params.resolution = 0.0;
  const model::Diagnostic& resolution =
      only_finding(params, model::SourceLocation{"(command line)"});
  CHECK(resolution.field == "resolution");
  CHECK(resolution.where.file == "(command line)");
  CHECK(resolution.expected.find("> 0") != std::string::npos);

  params = costmap::CostmapParams{};
  params.robot_radius = 0.4;
  params.size_y = 0.5;
  const model::Diagnostic& window =
      only_finding(params, model::SourceLocation{"scenario.yaml", 12, 3}, "costmap.");
  CHECK(window.field == "costmap.size_y");
  CHECK(window.where.line == 12);
  CHECK(window.problem.find("footprint") != std::string::npos);
  CHECK(window.expected.find("0.8 m") != std::string::npos);

  params = costmap::CostmapParams{};
  params.hit.hit_max = 70000;  // does not fit the 16-bit counts
  CHECK(only_finding(params, {}).field == "hit.hit_max");
  params = costmap::CostmapParams{};
  params.voxel.z_max = params.voxel.z_min;
  CHECK(only_finding(params, {}).field == "voxel.z_max");
  params = costmap::CostmapParams{};
  params.resolution = -1.0;
  CHECK_THROWS_AS(costmap::Costmap(params), model::InputError);
}

TEST_CASE("the costmap follows the robot and inflates what the layers see", "[costmap]") {
  costmap::CostmapParams params;
  params.size_x = 4.0;
  params.size_y = 4.0;
  params.resolution = 0.1;
  params.voxel.z_resolution = 0.1;
  params.voxel.unknown_threshold = 100;  // columns count as free unless occupied
  costmap::Costmap costmap(params);
  // A point 1 m ahead of a robot at x = 5, 0.5 m up.
  const model::PointCloud cloud = cloud_from({0.0f, 0.0f, 0.5f}, {{1.05f, 0.05f, 0.5f}});
  costmap::CloudObservation observation;
  observation.cloud = &cloud;
  observation.T_world_cloud = at_x(5.0);
  costmap.update(0.0, at_x(5.0), std::vector<costmap::CloudObservation>{observation});
  // Lattice cell of the robot (50, 0) sits at window cell (20, 20).
  CHECK(costmap.window().origin_cell == Eigen::Vector2i(30, -20));
  const auto obstacle = costmap.window().cell_of(model::Vec2(6.05, 0.05));
  REQUIRE(obstacle);
  CHECK(costmap.master().at(obstacle->x, obstacle->y) == costmap::cost::kLethal);
  CHECK(costmap.master().at(obstacle->x - 1, obstacle->y) ==
        costmap::cost::kInscribed);  // 0.1 m <= 0.1 m
  CHECK(int(costmap.master().at(obstacle->x - 3, obstacle->y)) ==
        138);  // 0.3 m: 252 exp(-0.6) = 138.3
  CHECK(costmap.hit_layer().counts().at(obstacle->x, obstacle->y) == 3);
}

TEST_CASE("the Hit Layer keeps an obstacle the 2D layer cleared while the robot waits",
          "[costmap]") {
  costmap::CostmapParams params;
  params.layer = costmap::ObstacleLayerKind::obstacle;
  params.size_x = 4.0;
  params.size_y = 4.0;
  params.resolution = 0.1;
  // The foam's edge seen once by a low camera, then only a lidar at 1 m whose rays pass over
  // it to the wall: in 2D the lidar clears the foam's cell at every step.
  const model::PointCloud camera = cloud_from({0.0f, 0.0f, 0.3f}, {{0.55f, 0.05f, 0.4f}});
  const model::PointCloud lidar = cloud_from({0.0f, 0.0f, 1.0f}, {{1.55f, 0.05f, 1.0f}});
  auto observe = [](const model::PointCloud& cloud) {
    costmap::CloudObservation o;
    o.cloud = &cloud;
    return o;
  };
  auto run = [&](bool hit_layer, bool moving) {
    params.use_hit_layer = hit_layer;
    costmap::Costmap costmap(params);
    costmap.update(0.0, model::Pose3::Identity(),
                   std::vector<costmap::CloudObservation>{observe(camera)});
    for (int step = 1; step <= 20; ++step) {
      costmap.update(0.1 * step, model::Pose3::Identity(),
                     std::vector<costmap::CloudObservation>{observe(lidar)}, moving);
    }
    const auto foam = costmap.window().cell_of(model::Vec2(0.55, 0.05));
    return costmap.master().at(foam->x, foam->y);
  };
  CHECK(run(true, false) == costmap::cost::kLethal);  // stationary: h stays at 3
  CHECK(run(true, true) != costmap::cost::kLethal);   // commanded to move: 3 decrements clear it
  CHECK(run(false, false) !=
        costmap::cost::kLethal);  // no Hit Layer: gone at the first lidar update
}

// nav2's ObservationBuffer (purgeStaleObservations, observation_buffer.cpp at f4108e5): a
// cloud is dropped once now - stamp > observation_persistence, so it still marks when its
// age equals the persistence. Times in quarters of a second are exact in binary.
TEST_CASE(
    "costmap: a source's observation_persistence keeps its cloud marking until it is "
    "older than that",
    "[costmap]") {
  costmap::CostmapParams params;
  params.layer = costmap::ObstacleLayerKind::obstacle;
  params.size_x = params.size_y = 4.0;
  params.resolution = 0.1;
  params.use_hit_layer = false;
  // The same foam and lidar as above: the lidar's 2D ray clears the foam's cell each update.
  const model::PointCloud camera = cloud_from({0.0f, 0.0f, 0.3f}, {{0.55f, 0.05f, 0.4f}});
  const model::PointCloud lidar = cloud_from({0.0f, 0.0f, 1.0f}, {{1.55f, 0.05f, 1.0f}});
  const auto foam_after = [&](double persistence, double until) {
    costmap::Costmap costmap(params);
    costmap::CloudObservation seen;
    seen.cloud = &camera;
    seen.source.observation_persistence = persistence;
    costmap.update(0.0, model::Pose3::Identity(), std::vector<costmap::CloudObservation>{seen});
    costmap::CloudObservation clearing;
    clearing.cloud = &lidar;
    for (double t = 0.25; t <= until; t += 0.25) {
      costmap.update(t, model::Pose3::Identity(), std::vector<costmap::CloudObservation>{clearing});
    }
    const auto foam = costmap.window().cell_of(model::Vec2(0.55, 0.05));
    return costmap.master().at(foam->x, foam->y);
  };
  CHECK(foam_after(0.0, 0.25) != costmap::cost::kLethal);  // nav2's default keeps no old cloud
  CHECK(foam_after(0.5, 0.25) == costmap::cost::kLethal);
  CHECK(foam_after(0.5, 0.5) == costmap::cost::kLethal);   // age 0.5 s = persistence: kept
  CHECK(foam_after(0.5, 0.75) != costmap::cost::kLethal);  // age 0.75 s: dropped, cleared
}

TEST_CASE("costmap: a persisted cloud marks where it was taken while the robot moves on",
          "[costmap]") {
  costmap::CostmapParams params;
  params.layer = costmap::ObstacleLayerKind::obstacle;
  params.size_x = params.size_y = 4.0;
  params.resolution = 0.1;
  params.use_hit_layer = false;
  // A robot-frame point 0.55 m ahead, 0.05 m left, 0.4 m up, taken with the robot at (1, 0)
  // facing +y: in the world it is at (1 - 0.05, 0.55) = (0.95, 0.55).
  const model::PointCloud camera = cloud_from({0.3f, 0.0f, 0.3f}, {{0.55f, 0.05f, 0.4f}});
  model::Pose3 T_world_robot = model::Pose3::Identity();
  T_world_robot.translate(model::Vec3(1.0, 0.0, 0.0));
  T_world_robot.rotate(Eigen::AngleAxisd(std::numbers::pi / 2, model::Vec3::UnitZ()));
  costmap::CloudObservation seen;
  seen.cloud = &camera;
  seen.T_world_cloud = T_world_robot;
  seen.source.observation_persistence = 2.0;
  costmap::Costmap costmap(params);
  costmap.update(0.0, T_world_robot, std::vector<costmap::CloudObservation>{seen});
  // One second later the robot stands 0.3 m further on, and a world-frame lidar ray at 1 m
  // crosses the point's cell from (0.95, -0.5) to (0.95, 1.5), clearing it in 2D.
  model::Pose3 moved = model::Pose3::Identity();
  moved.translate(model::Vec3(1.3, 0.0, 0.0));
  const model::PointCloud lidar = cloud_from({0.95f, -0.5f, 1.0f}, {{0.95f, 1.5f, 1.0f}});
  costmap::CloudObservation clearing;
  clearing.cloud = &lidar;
  costmap.update(1.0, moved, std::vector<costmap::CloudObservation>{clearing});
  CHECK(costmap.persisted_observations() == 1);
  const auto foam = costmap.window().cell_of(model::Vec2(0.95, 0.55));
  REQUIRE(foam);
  CHECK(costmap.master().at(foam->x, foam->y) == costmap::cost::kLethal);
  // Not where the robot-frame numbers would put it without the transform.
  const auto untransformed = costmap.window().cell_of(model::Vec2(0.55, 0.05));
  REQUIRE(untransformed);
  CHECK(costmap.master().at(untransformed->x, untransformed->y) != costmap::cost::kLethal);
}
