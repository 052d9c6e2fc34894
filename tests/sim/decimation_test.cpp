#include "rigdesign/sim/decimation.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/sim/noise_stream.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

using namespace rigdesign;

namespace {

// A 0.6 x 0.4 rad camera, or a lidar band of the same extent.
enum class Kind { camera, lidar };

model::SensorMode mode_of(Kind kind, double h, double v, double points) {
  model::SensorMode mode;
  mode.fov = model::FieldOfView(kind == Kind::camera ? model::pyramid_fov(0.6, 0.4)
                                                     : model::band_fov(0.6, -0.2, 0.2));
  mode.angular_resolution_h = h;
  mode.angular_resolution_v = v;
  mode.points_per_frame = points;
  return mode;
}

}  // namespace

TEST_CASE("decimation: cameras lose rows and columns, lidars only rays along the scan", "[sim]") {
  const model::SensorMode camera = mode_of(Kind::camera, 0.001, 0.002, 6400.0);
  const model::SensorMode sparse_camera = sim::decimated_mode(camera, 4, 3);
  CHECK(sparse_camera.angular_resolution_h == Approx(0.004));
  CHECK(*sparse_camera.angular_resolution_v == Approx(0.008));
  CHECK(sparse_camera.points_per_frame == Approx(400.0));  // 6400 / 4^2

  const model::SensorMode lidar = mode_of(Kind::lidar, 0.0035, 0.035, 28800.0);
  const model::SensorMode sparse_lidar = sim::decimated_mode(lidar, 4, 3);
  CHECK(sparse_lidar.angular_resolution_h == Approx(0.0105));
  CHECK(*sparse_lidar.angular_resolution_v == Approx(0.035));  // every ring kept
  CHECK(sparse_lidar.points_per_frame == Approx(9600.0));

  const model::SensorMode same = sim::decimated_mode(lidar, 4, 0);
  CHECK(same.angular_resolution_h == lidar.angular_resolution_h);
  CHECK(same.points_per_frame == lidar.points_per_frame);
}

TEST_CASE("decimation keeps every k-th ray of the camera's grid", "[sim]") {
  model::SensorMode camera = mode_of(Kind::camera, 0.6 / 40, 0.4 / 20, 800.0);
  const std::size_t full = sim::ray_pattern(camera).size();
  const std::size_t sparse = sim::ray_pattern(sim::decimated_mode(camera, 2, 1)).size();
  CHECK(full == 800);  // 40 x 20 pixels
  CHECK(sparse == 200);
}

TEST_CASE("noise streams: one per sensor, fixed by the seed", "[sim]") {
  auto first_draws = [](std::mt19937_64 rng) {
    return std::array<std::uint64_t, 3>{rng(), rng(), rng()};
  };
  CHECK(first_draws(sim::noise_stream(7, 2)) == first_draws(sim::noise_stream(7, 2)));
  CHECK(first_draws(sim::noise_stream(7, 2)) != first_draws(sim::noise_stream(7, 3)));
  CHECK(first_draws(sim::noise_stream(7, 2)) != first_draws(sim::noise_stream(8, 2)));
  // The seed's upper 32 bits count too.
  CHECK(first_draws(sim::noise_stream(7, 2)) !=
        first_draws(sim::noise_stream(7 + (std::uint64_t{1} << 32), 2)));
}
