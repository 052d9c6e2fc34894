#include "rigdesign/costmap/costmap.hpp"

#include <catch2/catch.hpp>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/model/input_error.hpp"

using namespace rigdesign;

namespace {

const Diagnostic& only_finding(const CostmapParams& params, const SourceLocation& where,
                               const std::string& prefix = {}) {
  static std::vector<Diagnostic> kept;
  try {
    check_costmap_params(params, where, prefix);
  } catch (const InputError& error) {
    kept = error.diagnostics();
    REQUIRE(kept.size() == 1);
    return kept.front();
  }
  FAIL("expected an InputError");
  return kept.front();
}

PointCloud cloud_from(const Point3f& origin, std::vector<Point3f> points) {
  PointCloud cloud;
  cloud.origin = origin;
  cloud.points = std::move(points);
  return cloud;
}

Pose3 at_x(double x) {
  return Pose3(Eigen::Translation3d(x, 0.0, 0.0));
}

}  // namespace

TEST_CASE("costmap parameters: bad resolution and a window smaller than the footprint",
          "[costmap]") {
  CostmapParams params;
  params.resolution = 0.0;
  const Diagnostic& resolution = only_finding(params, SourceLocation{"(command line)"});
  CHECK(resolution.field == "resolution");
  CHECK(resolution.where.file == "(command line)");
  CHECK(resolution.expected.find("> 0") != std::string::npos);

  params = CostmapParams{};
  params.robot_radius = 0.4;
  params.size_y = 0.5;
  const Diagnostic& window =
      only_finding(params, SourceLocation{"scenario.yaml", 12, 3}, "costmap.");
  CHECK(window.field == "costmap.size_y");
  CHECK(window.where.line == 12);
  CHECK(window.problem.find("footprint") != std::string::npos);
  CHECK(window.expected.find("0.8 m") != std::string::npos);

  params = CostmapParams{};
  params.hit.hit_max = 70000;  // does not fit the 16-bit counts
  CHECK(only_finding(params, {}).field == "hit.hit_max");
  params = CostmapParams{};
  params.voxel.z_max = params.voxel.z_min;
  CHECK(only_finding(params, {}).field == "voxel.z_max");
  params = CostmapParams{};
  params.resolution = -1.0;
  CHECK_THROWS_AS(Costmap(params), InputError);
}

TEST_CASE("the costmap follows the robot and inflates what the layers see", "[costmap]") {
  CostmapParams params;
  params.size_x = 4.0;
  params.size_y = 4.0;
  params.resolution = 0.1;
  params.voxel.z_resolution = 0.1;
  params.voxel.unknown_threshold = 100;  // columns count as free unless occupied
  Costmap costmap(params);
  // A point 1 m ahead of a robot at x = 5, 0.5 m up.
  const PointCloud cloud = cloud_from({0.0f, 0.0f, 0.5f}, {{1.05f, 0.05f, 0.5f}});
  CloudObservation observation;
  observation.cloud = &cloud;
  observation.T_world_cloud = at_x(5.0);
  costmap.update(0.0, at_x(5.0), std::vector<CloudObservation>{observation});
  // Lattice cell of the robot (50, 0) sits at window cell (20, 20).
  CHECK(costmap.window().origin_cell == Eigen::Vector2i(30, -20));
  const auto obstacle = costmap.window().cell_of(Vec2(6.05, 0.05));
  REQUIRE(obstacle);
  CHECK(costmap.master().at(obstacle->x, obstacle->y) == cost::kLethal);
  CHECK(costmap.master().at(obstacle->x - 1, obstacle->y) == cost::kInscribed);  // 0.1 m <= 0.1 m
  CHECK(int(costmap.master().at(obstacle->x - 3, obstacle->y)) ==
        138);  // 0.3 m: 252 exp(-0.6) = 138.3
  CHECK(costmap.hit_layer().counts().at(obstacle->x, obstacle->y) == 3);
}

TEST_CASE("the Hit Layer keeps an obstacle the 2D layer cleared while the robot waits",
          "[costmap]") {
  CostmapParams params;
  params.layer = ObstacleLayerKind::obstacle;
  params.size_x = 4.0;
  params.size_y = 4.0;
  params.resolution = 0.1;
  // The foam's edge seen once by a low camera, then only a lidar at 1 m whose rays pass over
  // it to the wall: in 2D the lidar clears the foam's cell at every step.
  const PointCloud camera = cloud_from({0.0f, 0.0f, 0.3f}, {{0.55f, 0.05f, 0.4f}});
  const PointCloud lidar = cloud_from({0.0f, 0.0f, 1.0f}, {{1.55f, 0.05f, 1.0f}});
  auto observe = [](const PointCloud& cloud) {
    CloudObservation o;
    o.cloud = &cloud;
    return o;
  };
  auto run = [&](bool hit_layer, bool moving) {
    params.use_hit_layer = hit_layer;
    Costmap costmap(params);
    costmap.update(0.0, Pose3::Identity(), std::vector<CloudObservation>{observe(camera)});
    for (int step = 1; step <= 20; ++step) {
      costmap.update(0.1 * step, Pose3::Identity(), std::vector<CloudObservation>{observe(lidar)},
                     moving);
    }
    const auto foam = costmap.window().cell_of(Vec2(0.55, 0.05));
    return costmap.master().at(foam->x, foam->y);
  };
  CHECK(run(true, false) == cost::kLethal);   // stationary: h stays at 3
  CHECK(run(true, true) != cost::kLethal);    // commanded to move: 3 decrements clear it
  CHECK(run(false, false) != cost::kLethal);  // no Hit Layer: gone at the first lidar update
}
