// Issue 36 item 2: OctoMap as paper 3 configured it, checked against OctoMap's log-odds update
// worked by hand: l(p) = ln(p / (1 - p)), one update per voxel per cloud, clamping at
// octomap_server's 0.12 / 0.97, occupied at l >= 0.
#include "rigdesign/occupancy/octomap_mapper.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

using namespace rigdesign;

namespace {

// One cloud from (0.05, 0.05, 1.05) with a point at x (y 0.05, z 1.05).
std::vector<model::PointCloud> ray_to(float x) {
  model::PointCloud cloud;
  cloud.origin = model::Point3f(0.05f, 0.05f, 1.05f);
  cloud.points = {{x, 0.05f, 1.05f}};
  return {cloud};
}

bool octomap_shows(const occupancy::OccupancyMapper& mapper, const costmap::VoxelKey& key) {
  const std::vector<costmap::VoxelKey> keys = mapper.occupied();
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

TEST_CASE("OctoMap hit 1: one hit occupies, nine misses free (clamp 0.97, miss 0.4)",
          "[occupancy][octomap]") {
  // Hit 1 takes the voxel to the clamp l(0.97) = 3.476. Each miss adds l(0.4) = -0.405:
  // after 8 misses 3.476 - 3.244 = 0.232 >= 0 (occupied), after 9 -0.17 (free).
  REQUIRE(std::log(0.97 / 0.03) + 8 * std::log(0.4 / 0.6) == Approx(0.232).margin(1e-3));
  const auto mapper = occupancy::make_octomap_mapper({});  // 0.1 m, hit 1, miss 0.4
  const costmap::VoxelKey voxel{10, 0, 10};                // holds x = 1.05
  mapper->update(0.0, ray_to(1.05f), true);
  CHECK(octomap_shows(*mapper, voxel));
  CHECK(mapper->occupied().size() == 1);
  for (int miss = 1; miss <= 8; ++miss) {
    mapper->update(0.2 * miss, ray_to(2.05f), true);  // the ray passes through the voxel
    CHECK(octomap_shows(*mapper, voxel));
  }
  mapper->update(2.0, ray_to(2.05f), true);
  CHECK_FALSE(octomap_shows(*mapper, voxel));
  // And the ninth miss's own end voxel is occupied from its first (and only) hit.
  CHECK(octomap_shows(*mapper, {20, 0, 10}));
}

TEST_CASE("OctoMap hit 0.7: after clamping at the bottom, three hits to occupy",
          "[occupancy][octomap]") {
  // From the clamp l(0.12) = -1.992: one hit -1.145, two -0.298, three +0.549.
  occupancy::OctoMapParams params;
  params.hit = 0.7;
  const auto mapper = occupancy::make_octomap_mapper(params);
  const costmap::VoxelKey voxel{10, 0, 10};
  for (int miss = 0; miss < 10; ++miss) mapper->update(0.0, ray_to(2.05f), true);
  for (int hit = 1; hit <= 3; ++hit) {
    mapper->update(0.0, ray_to(1.05f), true);
    CHECK(octomap_shows(*mapper, voxel) == (hit == 3));
  }
}

TEST_CASE("OctoMap: a ground point's ray clears, its end voxel is left alone",
          "[occupancy][octomap]") {
  const auto mapper = occupancy::make_octomap_mapper({});
  // A point on the floor (z 0.05 < min_height 0.1) marks nothing.
  model::PointCloud cloud;
  cloud.origin = model::Point3f(0.05f, 0.05f, 1.05f);
  cloud.points = {{1.05f, 0.05f, 0.05f}};
  mapper->update(0.0, std::vector<model::PointCloud>{cloud}, true);
  CHECK(mapper->occupied().empty());
  CHECK_THROWS_AS(occupancy::make_octomap_mapper({0.1, 1.5}), std::invalid_argument);
}
