#include "rigdesign/sim/sensor_simulator.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

using namespace rigdesign;

namespace {

// A 20 m x 20 m wall in the plane x = 2, facing the origin.
model::TriangleMesh wall_at_two_metres() {
  model::TriangleMesh wall;
  wall.vertices = {{2, -10, -10}, {2, 10, -10}, {2, 10, 10}, {2, -10, 10}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  return wall;
}

model::SensorMode depth_camera() {
  model::SensorMode mode;
  mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(60), model::deg_to_rad(40)));
  mode.angular_resolution_h = mode.fov.horizontal() / 64;
  mode.angular_resolution_v = mode.fov.vertical() / 48;
  mode.min_range = 0.1;
  mode.max_range = 10;
  mode.noise.a = 0.01;
  return mode;
}

}  // namespace

TEST_CASE("a depth camera facing a wall at 2 m returns every pixel at 2 m within 3 sigma") {
  const sim::RayCaster scene(wall_at_two_metres());
  const model::SensorMode mode = depth_camera();
  const std::vector<model::Vec3> rays = sim::ray_pattern(mode);
  REQUIRE(rays.size() == 64 * 48);
  std::mt19937_64 rng(1);
  const model::PointCloud cloud =
      sim::simulate_frame(scene, mode, rays, model::Pose3::Identity(), {}, rng);
  CHECK(cloud.size() == 64 * 48);  // every ray hits the wall
  // Noise is along the ray, so a point's depth x deviates by at most |noise| from 2 m.
  std::size_t within = 0;
  double mean = 0.0;
  for (const model::Point3f& p : cloud.points) {
    within += std::abs(p.x() - 2.0) <= 3 * 0.01 ? 1 : 0;
    mean += p.x();
  }
  mean /= static_cast<double>(cloud.size());
  CHECK(static_cast<double>(within) >=
        0.995 * static_cast<double>(cloud.size()));  // Gaussian: 99.73 %
  CHECK(std::abs(mean - 2.0) < 0.002);
  // Without noise, exactly on the wall; dropout removes its share.
  sim::SimulationSettings exact;
  exact.add_noise = false;
  const model::PointCloud clean =
      sim::simulate_frame(scene, mode, rays, model::Pose3::Identity(), exact, rng);
  for (const model::Point3f& p : clean.points) CHECK(std::abs(p.x() - 2.0f) < 1e-5f);
  sim::SimulationSettings lossy;
  lossy.dropout = 0.25;
  const double kept = static_cast<double>(
      sim::simulate_frame(scene, mode, rays, model::Pose3::Identity(), lossy, rng).size());
  CHECK(std::abs(kept / (64 * 48) - 0.75) < 0.03);
}

TEST_CASE("range limits, poses and the same seed") {
  const sim::RayCaster scene(wall_at_two_metres());
  model::SensorMode mode = depth_camera();
  mode.max_range = 1.5;
  std::mt19937_64 rng(2);
  CHECK(sim::simulate_frame(scene, mode, sim::ray_pattern(mode), model::Pose3::Identity(), {}, rng)
            .empty());
  mode.max_range = 10;
  // Turned 180 degrees, the camera looks away from the wall.
  const model::Pose3 backwards =
      model::pose_from_xyz_rpy(model::Vec3::Zero(), model::Vec3(0, 0, model::deg_to_rad(180)));
  CHECK(sim::simulate_frame(scene, mode, sim::ray_pattern(mode), backwards, {}, rng).empty());
  std::mt19937_64 a(7), b(7);
  CHECK(sim::simulate_frame(scene, mode, sim::ray_pattern(mode), model::Pose3::Identity(), {}, a)
            .points ==
        sim::simulate_frame(scene, mode, sim::ray_pattern(mode), model::Pose3::Identity(), {}, b)
            .points);
}

TEST_CASE("ray patterns follow the datasheet: VLP-16 rings, a 2D fan") {
  model::SensorMode vlp;
  vlp.fov = model::FieldOfView(
      model::band_fov(2 * 3.141592653589793, model::deg_to_rad(-15), model::deg_to_rad(15)));
  vlp.angular_resolution_h = model::deg_to_rad(0.3);
  vlp.angular_resolution_v = model::deg_to_rad(2.0);
  CHECK(sim::ray_pattern(vlp).size() == 16 * 1200);  // 16 lasers x 360 / 0.3
  model::SensorMode lms;
  lms.fov = model::FieldOfView(model::planar_fov(model::deg_to_rad(270), 0.0));
  lms.angular_resolution_h = model::deg_to_rad(0.5);
  CHECK(sim::ray_pattern(lms).size() == 541);  // 270 / 0.5 + 1, as the LMS1xx delivers
}
