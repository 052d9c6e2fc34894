// Issue 36 item 1: paper 3's ground truth keeps only the actor's points a sensor saw. A box
// actor half hidden behind a wall, seen by a noise-free scanning sensor: its truth voxels lie
// on the face towards the sensor and only where the wall does not hide it (derived by hand).
#include <catch2/catch.hpp>
#include <numbers>
#include <random>

#include "rigdesign/model/units.hpp"
#include "rigdesign/occupancy/occupancy_actor_points.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"
#include "support/box_mesh.hpp"

using namespace rigdesign;

TEST_CASE("ground truth from sensor points: a hidden face gives no truth voxel", "[occupancy]") {
  // Actor: x 2.0..2.4, y -0.5..0.5, z 0..1. Wall: x 1.0..1.05, y 0..1, z 0..2, hiding the
  // actor's +y half from a sensor at the origin (the line from the origin to (2, 0) grazes the
  // wall's corner at y = 0, so rays to y > 0 on the actor pass x = 1 at y > 0: inside it).
  const model::TriangleMesh actor = test::box_mesh({2.0, -0.5, 0.0}, {2.4, 0.5, 1.0});
  model::TriangleMesh scene = test::box_mesh({1.0, 0.0, 0.0}, {1.05, 1.0, 2.0});
  scene.append(actor);
  const sim::RayCaster scene_caster(scene);
  const sim::RayCaster actor_caster(actor);

  model::SensorMode mode;  // a 16-ring lidar, 0.5 deg steps, no noise, at 0.5 m height
  mode.fov = model::FieldOfView(
      model::band_fov(2 * std::numbers::pi, model::deg_to_rad(-15), model::deg_to_rad(15)));
  mode.angular_resolution_h = model::deg_to_rad(0.5);
  mode.angular_resolution_v = model::deg_to_rad(2.0);
  mode.min_range = 0.1;
  mode.max_range = 10.0;
  sim::SimulationSettings settings;
  settings.add_noise = false;
  std::mt19937_64 rng(1);
  const model::Pose3 T_world_sensor(Eigen::Translation3d(0.0, 0.0, 0.5));
  const model::PointCloud cloud = sim::simulate_frame(scene_caster, mode, sim::ray_pattern(mode),
                                                      T_world_sensor, settings, rng);

  Eigen::AlignedBox3d box(model::Vec3(2.0, -0.5, 0.0), model::Vec3(2.4, 0.5, 1.0));
  const std::vector<model::Vec3> points =
      occupancy::actor_points(cloud, scene_caster, actor_caster, box, 0.15);
  REQUIRE_FALSE(points.empty());
  for (const model::Vec3& p : points) {
    CHECK(p.x() == Approx(2.0).margin(1e-9));  // the face towards the sensor only
    CHECK(p.y() <= 1e-9);                      // the wall hides y > 0
  }
  // The wall's own points and the points on the floor-less far side are not the actor's.
  std::size_t on_wall = 0;
  for (const model::Point3f& p : cloud.points) on_wall += p.x() < 1.06f && p.y() >= 0.0f;
  CHECK(on_wall > 0);

  occupancy::VoxelLattice lattice;  // 0.1 m voxels, z 0..2 m
  const std::vector<costmap::VoxelKey> keys = occupancy::voxelise_points(points, lattice, 0.1);
  REQUIRE_FALSE(keys.empty());
  for (const costmap::VoxelKey& key : keys) {
    CHECK(key.x == 20);  // floor(2.0 / 0.1): the front face; the back at x = 2.4 (key 24) unseen
    CHECK(key.y < 0);    // floor(y / 0.1) for y in [-0.5, 0)
    CHECK(key.z >= 1);   // heights from 0.1 m
  }
  // Unique and ascending.
  for (std::size_t i = 1; i < keys.size(); ++i) CHECK(keys[i - 1] < keys[i]);
}
