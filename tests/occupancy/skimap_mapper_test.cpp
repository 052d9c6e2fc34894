// Issue 36 item 3: SkiMap's weighted voxels on a hand-counted case: each point adds 1 to its
// voxel, a voxel is occupied from min_voxel_weight on, and nothing is ever cleared.
#include "rigdesign/occupancy/skimap_mapper.hpp"

#include <catch2/catch.hpp>

using namespace rigdesign;

TEST_CASE("SkiMap: the weight threshold on hand-counted points", "[occupancy][skimap]") {
  occupancy::SkiMapParams params;  // 0.1 m voxels, points below 0.1 m left out
  params.min_voxel_weight = 3;
  const auto mapper = occupancy::make_skimap_mapper(params);
  // Voxel A = (10, 0, 10): three points; voxel B = (-3, 2, 5): one point; one ground point.
  model::PointCloud first;
  first.points = {{1.01f, 0.02f, 1.01f},
                  {1.05f, 0.05f, 1.05f},
                  {1.09f, 0.09f, 1.09f},
                  {-0.25f, 0.25f, 0.55f},
                  {0.5f, 0.5f, 0.05f}};
  std::vector<model::PointCloud> clouds = {first};
  mapper->update(0.0, clouds, true);
  CHECK(mapper->occupied() == std::vector<costmap::VoxelKey>{{10, 0, 10}});
  // Two more points in B, none in A: B reaches 3; A, which nothing sees now, stays.
  model::PointCloud second;
  second.points = {{-0.21f, 0.21f, 0.51f}, {-0.29f, 0.29f, 0.59f}};
  clouds = {second};
  mapper->update(0.2, clouds, true);
  CHECK(mapper->occupied() == std::vector<costmap::VoxelKey>{{-3, 2, 5}, {10, 0, 10}});
  // A ray through A to a point beyond it changes nothing: SkiMap casts no rays.
  model::PointCloud through;
  through.origin = model::Point3f(0.05f, 0.05f, 1.05f);
  through.points = {{2.05f, 0.05f, 1.05f}};
  clouds = {through};
  mapper->update(0.4, clouds, true);
  CHECK(mapper->occupied() == std::vector<costmap::VoxelKey>{{-3, 2, 5}, {10, 0, 10}});
}

TEST_CASE("SkiMap: parameters out of range are refused", "[occupancy][skimap]") {
  occupancy::SkiMapParams params;
  params.min_voxel_weight = 0.5;
  CHECK_THROWS_AS(occupancy::make_skimap_mapper(params), std::invalid_argument);
  params = {};
  params.voxel = 0.001;
  CHECK_THROWS_AS(occupancy::make_skimap_mapper(params), std::invalid_argument);
}
