// Issue 52 item 2(a): what a sensor's own robot hides from it in the simulation. A VLP-16 above
// a cylinder body with a D435 in front of it; the distances by hand from the rig's numbers and
// sensors.yaml's housings (D435: box 0.025 x 0.09 x 0.025 m centred at (-0.0082, -0.0175, 0)).
#include "rigdesign/sim/robot_occlusion.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

model::Vec3 direction(double azimuth_deg, double elevation_deg) {
  const double a = model::deg_to_rad(azimuth_deg), e = model::deg_to_rad(elevation_deg);
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

}  // namespace

TEST_CASE("simulation: the robot's body and the other housings stop a sensor's rays", "[sim]") {
  test::TempFolder folder;
  const std::string rig_file = folder.write("rig.yaml", R"(name: occlusion probe
body: {radius: 0.25, height: 0.5}
distance_of_interest: 2.0
mounts:
  - {id: lidar, sensor: velodyne_vlp16, mode: vlp16_10hz, pose: {xyz: [0, 0, 0.55], rpy_deg: [0, 0, 0]}}
  - {id: camera, sensor: realsense_d435, mode: z16_848x480_30, pose: {xyz: [0.3, 0, 0.55], rpy_deg: [0, 0, 0]}}
)");
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(rig_file);
  const model::Mount& lidar = rig.mounts[0];
  const model::SensorMode& mode = library.resolved_mode(lidar.sensor_id, lidar.mode_id);
  const std::vector<model::Vec3> rays = {direction(0, 0), direction(90, -14), direction(90, 14)};
  const std::vector<double> free = sim::robot_free_ranges(rig, library, lidar, mode, rays);
  REQUIRE(free.size() == 3);
  // Forward: the D435 housing's back face, x = 0.3 - 0.0082 - 0.025 / 2.
  CHECK(free[0] == Approx(0.3 - 0.0082 - 0.0125).margin(1e-9));
  // 14 deg down to the left: the body's top, 0.05 m below the origin, at 0.05 / sin 14 deg
  // (0.2 m out, within the 0.25 m radius).
  CHECK(free[1] == Approx(0.05 / std::sin(model::deg_to_rad(14))).margin(1e-9));
  // 14 deg up: nothing of the robot.
  CHECK(std::isinf(free[2]));

  // The simulated frame: a wall 2 m ahead of the lidar; the forward ray ends on the D435.
  model::TriangleMesh wall;
  wall.vertices = {{2, -10, -10}, {2, 10, -10}, {2, 10, 10}, {2, -10, 10}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  const sim::RayCaster caster(wall);
  const std::vector<model::Vec3> forward = {direction(0, 0), direction(10, 0)};
  const std::vector<double> forward_free =
      sim::robot_free_ranges(rig, library, lidar, mode, forward);
  std::mt19937_64 rng(1);
  sim::SimulationSettings settings;
  settings.add_noise = false;
  const model::PointCloud with_robot =
      sim::simulate_frame(caster, mode, forward, lidar.T_robot_sensor, settings, rng, forward_free);
  // 10 deg left passes beside the housing (its edge at y = -0.0175 + 0.045 = 0.0275 m, the ray
  // at y = 0.28 tan 10 deg = 0.049 m there) and reaches the wall.
  REQUIRE(with_robot.points.size() == 1);
  CHECK(with_robot.points[0].x() == Approx(2.0).margin(1e-5));
  std::mt19937_64 rng_again(1);
  CHECK(sim::simulate_frame(caster, mode, forward, lidar.T_robot_sensor, settings, rng_again)
            .points.size() == 2);
}

TEST_CASE("simulation: the UR Cleaner's top VLP-16 loses its five lowest rings to the body",
          "[sim]") {
  // ur_cleaner.yaml: a cylinder of radius 0.45 m and height 1.0 m, the VLP-16 at z = 1.04 m on
  // the axis. A ring at elevation e meets the top at 0.04 / tan(-e) from the axis, inside the
  // 0.45 m rim when -e > atan(0.04 / 0.45) = 5.08 deg: the rings at -7, -9, ..., -15 deg
  // (sensors.yaml: 16 rings 2 deg apart from -15 deg), 5 of 16; the others clear it.
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(test::source_path("rigs/ur_cleaner.yaml"));
  const model::Mount* lidar = rig.find_mount("top_lidar");
  REQUIRE(lidar != nullptr);
  const model::SensorMode& mode = library.resolved_mode(lidar->sensor_id, lidar->mode_id);
  const std::vector<model::Vec3> rays = sim::ray_pattern(mode);
  REQUIRE(rays.size() % 16 == 0);
  const std::vector<double> free = sim::robot_free_ranges(rig, library, *lidar, mode, rays);
  std::size_t stopped = 0;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const bool low_ring = std::asin(rays[r].z()) < -model::deg_to_rad(6);
    CHECK((free[r] < mode.max_range) == low_ring);
    stopped += free[r] < mode.max_range ? 1 : 0;
  }
  CHECK(stopped == 5 * rays.size() / 16);
}
