// Mean pooling of an organised depth cloud (paper 3's RGB-D downsampling), on hand-made pixels,
// and the simulator's organised output that feeds it.
#include "rigdesign/sim/mean_pooling.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "rigdesign/model/units.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"
#include "support/box_mesh.hpp"

using namespace rigdesign;

TEST_CASE("mean pooling averages each block's returns", "[sim]") {
  constexpr float nan = std::numeric_limits<float>::quiet_NaN();
  // 3 rows x 4 columns, pooled 2 x 2: blocks (rows 0-1, columns 0-1), (0-1, 2-3), (2, 0-1),
  // (2, 2-3); the last holds only NaN and gives no point.
  model::PointCloud organised;
  organised.origin = model::Point3f(1, 2, 3);
  organised.points = {{1, 0, 0}, {3, 0, 0}, {0, 0, 4},       {nan, nan, nan},  //
                      {1, 2, 0}, {3, 2, 0}, {0, 0, 8},       {0, 3, 0},        //
                      {5, 5, 5}, {7, 7, 7}, {nan, nan, nan}, {nan, nan, nan}};
  const model::PointCloud pooled = sim::mean_pool(organised, 4, 2);
  REQUIRE(pooled.size() == 3);
  CHECK(pooled.points[0].isApprox(model::Point3f(2, 1, 0)));  // (1+3+1+3)/4, (0+0+2+2)/4
  CHECK(pooled.points[1].isApprox(model::Point3f(0, 1, 4)));  // three returns: (0+0+0)/3, ...
  CHECK(pooled.points[2].isApprox(model::Point3f(6, 6, 6)));
  CHECK(pooled.origin == organised.origin);
  CHECK_THROWS_AS(sim::mean_pool(organised, 5, 2), std::invalid_argument);
}

TEST_CASE("an organised frame keeps every pixel in place, misses as NaN", "[sim]") {
  // A 4 x 3 pixel camera looking along +x at a wall x = 2 that covers only y > 0 (the pixels
  // left of centre: REP-103's +y is left).
  const sim::RayCaster wall(test::box_mesh({2.0, 0.0, -5.0}, {2.1, 5.0, 5.0}));
  model::SensorMode mode;
  mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(40), model::deg_to_rad(30)));
  mode.angular_resolution_h = model::deg_to_rad(10);
  mode.angular_resolution_v = model::deg_to_rad(10);
  mode.min_range = 0.1;
  mode.max_range = 10.0;
  const std::vector<model::Vec3> rays = sim::ray_pattern(mode);
  REQUIRE(rays.size() == 12);
  CHECK(sim::pattern_columns(rays) == 4);
  std::mt19937_64 rng(1);
  sim::SimulationSettings settings;
  settings.add_noise = false;
  settings.keep_misses = true;
  const model::PointCloud cloud =
      sim::simulate_frame(wall, mode, rays, model::Pose3::Identity(), settings, rng);
  REQUIRE(cloud.size() == 12);
  for (std::size_t i = 0; i < 12; ++i) {
    INFO(i);
    CHECK(cloud.points[i].allFinite() == (rays[i].y() > 0.0));  // the wall's side only
  }
}
