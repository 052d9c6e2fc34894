// Issue 36 item 3: Voxblox's projective TSDF on single rays, every value computed by hand from
// the method as Voxblox's paper states it (projective distance, 1/z^2 weight, linear drop-off
// from -epsilon to -delta, weighted mean, merged integrator).
#include "rigdesign/occupancy/voxblox_mapper.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace rigdesign;

namespace {

// A sensor at (0.05, 0.05, 1.05), looking along +x, with the given points.
model::PointCloud ray_cloud(std::initializer_list<model::Point3f> points) {
  model::PointCloud cloud;
  cloud.origin = model::Point3f(0.05f, 0.05f, 1.05f);
  cloud.points = points;
  return cloud;
}

}  // namespace

TEST_CASE("Voxblox TSDF: one ray's distances and weights by hand", "[occupancy][voxblox]") {
  // Voxel 0.1 m, truncation 0.2 m: the ray runs from the origin to 0.2 m behind the point.
  // The point lies 1.0 m ahead at x = 1.05 (voxel 10's centre), depth 1 m: weight 1 / 1^2 = 1.
  // Voxel k's centre is x = 0.1 k + 0.05, so d = 1.0 - (0.1 k + 0.05 - 0.05) = 1 - 0.1 k.
  occupancy::VoxbloxParams params;
  params.truncation = 0.2;
  occupancy::VoxbloxTsdf tsdf(params);
  tsdf.integrate(ray_cloud({{1.05f, 0.05f, 1.05f}}), occupancy::DepthAxis::optical);
  const auto at = [&](int k) { return tsdf.at({k, 0, 10}); };
  CHECK(at(10).distance == Approx(0.0).margin(1e-6));  // the surface voxel
  CHECK(at(10).weight == Approx(1.0));
  CHECK(at(9).distance == Approx(0.1));  // in front: d = 0.1
  CHECK(at(9).weight == Approx(1.0));
  CHECK(at(2).distance == Approx(0.2));  // d = 0.8, truncated to delta
  // One voxel behind (d = -0.1 = -epsilon): still full weight.
  CHECK(at(11).distance == Approx(-0.1));
  CHECK(at(11).weight == Approx(1.0));
  // d = -0.2 = -delta: the drop-off (delta + d) / (delta - epsilon) = 0, so no update.
  CHECK(at(12).weight == 0.0f);
  CHECK(at(13).weight == 0.0f);                // beyond the ray's end
  CHECK(tsdf.at({10, 1, 10}).weight == 0.0f);  // off the ray
  // voxblox_ros's occupied_nodes: weight > 1e-3 and d <= one voxel (0.1 m): the surface voxel,
  // the one in front (d = 0.1) and the one behind (d = -0.1).
  const std::vector<costmap::VoxelKey> occupied = tsdf.occupied();
  CHECK(occupied == std::vector<costmap::VoxelKey>{{9, 0, 10}, {10, 0, 10}, {11, 0, 10}});
  // Its surface_pointcloud: weight and |d| < 0.75 voxel = 0.075 m: only the surface voxel.
  occupancy::VoxbloxParams surface_params = params;
  surface_params.occupied_rule = occupancy::VoxbloxOccupiedRule::surface_pointcloud;
  occupancy::VoxbloxTsdf surface(surface_params);
  surface.integrate(ray_cloud({{1.05f, 0.05f, 1.05f}}), occupancy::DepthAxis::optical);
  CHECK(surface.occupied() == std::vector<costmap::VoxelKey>{{10, 0, 10}});

  // A second cloud whose point lies 1.05 m ahead (x = 1.1, voxel 11): weight 1 / 1.05^2.
  // Voxel 10 gets d = 1.05 - 1.0 = 0.05: fused (0 x 1 + 0.05 w) / (1 + w).
  tsdf.integrate(ray_cloud({{1.1f, 0.05f, 1.05f}}), occupancy::DepthAxis::optical);
  const double w = 1.0 / (1.05 * 1.05);
  CHECK(at(10).weight == Approx(1.0 + w));
  CHECK(at(10).distance == Approx(0.05 * w / (1.0 + w)).epsilon(1e-5));
  // Voxel 12: d = 1.05 - 1.2 = -0.15, between -epsilon and -delta: weight w x (0.2 - 0.15) /
  // (0.2 - 0.1) = w / 2; it held nothing, so its distance is -0.15.
  CHECK(at(12).weight == Approx(w / 2).epsilon(1e-5));
  CHECK(at(12).distance == Approx(-0.15).epsilon(1e-5));
}

TEST_CASE("Voxblox TSDF: merged points, constant weight, depth axes, clearing rays",
          "[occupancy][voxblox]") {
  occupancy::VoxbloxParams params;  // voxel 0.1, truncation 0.1 (paper 3's reference row)
  SECTION("two points in one voxel merge into one ray with their summed weight") {
    params.use_const_weight = true;
    occupancy::VoxbloxTsdf tsdf(params);
    // Mean of x = 1.02 and 1.08 is 1.05: d = 0 at voxel 10 with weight 1 + 1.
    tsdf.integrate(ray_cloud({{1.02f, 0.05f, 1.05f}, {1.08f, 0.05f, 1.05f}}),
                   occupancy::DepthAxis::frame_z);
    CHECK(tsdf.at({10, 0, 10}).weight == Approx(2.0));
    CHECK(tsdf.at({10, 0, 10}).distance == Approx(0.0).margin(1e-6));
    CHECK(tsdf.at({5, 0, 10}).distance == Approx(0.1));  // d = 0.5, truncated to 0.1
  }
  SECTION("a lidar's weight takes the frame's z: a level point has none") {
    occupancy::VoxbloxTsdf tsdf(params);
    // The point lies level with the sensor (z = 0 in its frame): weight 1 / 0^2 -> none.
    tsdf.integrate(ray_cloud({{1.05f, 0.05f, 1.05f}}), occupancy::DepthAxis::frame_z);
    CHECK(tsdf.at({10, 0, 10}).weight == 0.0f);
    // 0.5 m below the sensor (z = -0.5): weight 1 / 0.25 = 4.
    tsdf.integrate(ray_cloud({{1.05f, 0.05f, 0.55f}}), occupancy::DepthAxis::frame_z);
    CHECK(tsdf.at({10, 0, 5}).weight == Approx(4.0).epsilon(1e-5));
  }
  SECTION("a point beyond max_ray_length only clears, stopping delta before it") {
    params.use_const_weight = true;
    params.max_ray_length = 0.8;
    occupancy::VoxbloxTsdf tsdf(params);
    // Range 1.0 > 0.8: the clearing ray ends at min(1.0 - 0.1, 0.8) = 0.8 m, at x = 0.85
    // (voxel 8); every voxel on it holds d = 1 - 0.1 k >= 0.2, truncated to 0.1.
    tsdf.integrate(ray_cloud({{1.05f, 0.05f, 1.05f}}), occupancy::DepthAxis::optical);
    CHECK(tsdf.at({8, 0, 10}).weight == Approx(1.0));
    CHECK(tsdf.at({8, 0, 10}).distance == Approx(0.1));
    CHECK(tsdf.at({9, 0, 10}).weight == 0.0f);
    CHECK(tsdf.at({10, 0, 10}).weight == 0.0f);
    // occupied_nodes shows free space too when truncation <= voxel (d = +0.1 <= 0.1): every
    // voxel the clearing ray crossed, up to voxel 8, and nothing past it.
    const std::vector<costmap::VoxelKey> nodes = tsdf.occupied();
    CHECK(std::find(nodes.begin(), nodes.end(), costmap::VoxelKey{8, 0, 10}) != nodes.end());
    for (const costmap::VoxelKey& key : nodes) {
      CHECK(key.x <= 8);
      CHECK(key.y == 0);
      CHECK(key.z == 10);
    }
    // surface_pointcloud (|d| < 0.075 m) shows none of it.
    params.occupied_rule = occupancy::VoxbloxOccupiedRule::surface_pointcloud;
    occupancy::VoxbloxTsdf surface(params);
    surface.integrate(ray_cloud({{1.05f, 0.05f, 1.05f}}), occupancy::DepthAxis::optical);
    CHECK(surface.occupied().empty());
  }
}
