// A window-matching depth camera (issue 54 item 1): what a pixel on a thin pole reports, each
// expected range worked out by hand from the scene's boxes and the window's geometry.
#include "rigdesign/sim/depth_matching.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"
#include "support/box_mesh.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

// The Kinect's window as sensors.yaml states it: 9 px of a 640-px image spanning 57 deg,
// baseline 7.5 cm. Angle 9 x 57 / 640 = 0.8016 deg = 0.013991 rad; focal length
// 320 / tan(28.5 deg) = 589.2 px, so baseline x focal = 44.19 m px.
model::DepthMatching kinect_window() {
  model::DepthMatching matching;
  matching.window_px = 9;
  matching.window_angle = 9.0 * model::deg_to_rad(57.0) / 640.0;
  matching.baseline_focal = 0.075 * 320.0 / std::tan(model::deg_to_rad(28.5));
  return matching;
}

// A wall whose face is the plane x = 3 m, and a pole from the floor up, its front face at
// x = 2 m, `width` [m] across y, centred on y = 0. The camera sits at (0, 0, 0.5) looking
// along +x, so the centre ray meets the pole's front face (or the wall) head on.
model::TriangleMesh pole_before_wall(double width) {
  model::TriangleMesh scene = test::box_mesh({3.0, -5.0, -1.0}, {3.2, 5.0, 3.0});
  scene.append(test::box_mesh({2.0, -width / 2, 0.0}, {2.04, width / 2, 1.5}));
  return scene;
}

const model::Vec3 kOrigin(0.0, 0.0, 0.5);
const model::Vec3 kForward(1.0, 0.0, 0.0);
const model::Vec3 kUp(0.0, 0.0, 1.0);
constexpr double kNoRobot = std::numeric_limits<double>::infinity();

// The camera at kOrigin looking along the world's +x, and settings without range noise.
model::Pose3 camera_pose() {
  model::Pose3 T_world_sensor = model::Pose3::Identity();
  T_world_sensor.translation() = kOrigin;
  return T_world_sensor;
}
sim::SimulationSettings noiseless() {
  sim::SimulationSettings settings;
  settings.add_noise = false;
  return settings;
}

}  // namespace

TEST_CASE("depth matching: a pole filling the window keeps its depth", "[sim]") {
  // The window's rays are tan(a/3) = 4.664e-3 apart per metre: 9.33 mm at 2 m. A 30 mm pole
  // holds all three columns (+-9.33 mm), and it is 1 m tall: all nine rays, 2 m.
  const sim::RayCaster scene(pole_before_wall(0.030));
  const std::optional<double> seen =
      sim::matched_range(scene, kOrigin, kForward, kUp, 2.0, kinect_window(), kNoRobot);
  REQUIRE(seen);
  CHECK(*seen == Approx(2.0).margin(1e-9));
}

TEST_CASE("depth matching: a pole thinner than a third of the window takes the wall's depth",
          "[sim]") {
  // A 5 mm pole holds only the centre column (+-2.5 mm < 9.33 mm): 3 of 9 rays at 2 m. The
  // side columns meet the wall 3 m away, at ranges 3 / cos(atan(4.664e-3 x k)) for the rows,
  // within 0.1 mm of 3 m; 3 m and 2 m are 4.2 disparity pixels apart (44.19 x (1/2 - 1/3)),
  // one surface being under a pixel. Six of nine rays: the wall, at the first such ray's
  // range (top row, left column: 3 / cos of the angle whose tangent is 4.664e-3 x sqrt(2)).
  const sim::RayCaster scene(pole_before_wall(0.005));
  const std::optional<double> seen =
      sim::matched_range(scene, kOrigin, kForward, kUp, 2.0, kinect_window(), kNoRobot);
  REQUIRE(seen);
  const double t = std::tan(kinect_window().window_angle / 3.0);
  CHECK(*seen == Approx(3.0 * std::sqrt(1.0 + 2.0 * t * t)).margin(1e-6));
}

TEST_CASE("depth matching: a window split three ways reports nothing", "[sim]") {
  // Centre column on the 5 mm pole (2 m); the left column (+y, 11.66 mm off the axis at
  // 2.5 m) meets a panel at x = 2.5 m from y = 5 mm outwards, which the centre column
  // (y = 0) and the right column (-y) miss; the right column meets the wall at 3 m.
  // Three rays each: no surface fills most of the window.
  model::TriangleMesh scene_mesh = pole_before_wall(0.005);
  scene_mesh.append(test::box_mesh({2.5, 0.005, -1.0}, {2.6, 1.0, 3.0}));
  const sim::RayCaster scene(scene_mesh);
  CHECK_FALSE(sim::matched_range(scene, kOrigin, kForward, kUp, 2.0, kinect_window(), kNoRobot));
}

TEST_CASE("depth matching in a frame: a mode with a window loses the thin pole, off keeps it",
          "[sim]") {
  model::SensorMode mode;
  mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(1.0), model::deg_to_rad(1.0)));
  mode.angular_resolution_h = mode.fov.horizontal();  // one ray, along the axis
  mode.angular_resolution_v = mode.fov.vertical();
  mode.min_range = 0.5;
  mode.max_range = 4.0;
  mode.depth_matching = kinect_window();
  const std::vector<model::Vec3> rays = {kForward};
  const sim::RayCaster scene(pole_before_wall(0.005));
  const model::Pose3 T_world_sensor = camera_pose();
  sim::SimulationSettings settings = noiseless();
  std::mt19937_64 rng(1);
  const model::PointCloud matched =
      sim::simulate_frame(scene, mode, rays, T_world_sensor, settings, rng);
  REQUIRE(matched.size() == 1);
  CHECK(matched.points[0].x() == Approx(3.0).margin(1e-3));  // the wall behind the pole
  settings.depth_matching = false;
  const model::PointCloud own =
      sim::simulate_frame(scene, mode, rays, T_world_sensor, settings, rng);
  REQUIRE(own.size() == 1);
  CHECK(own.points[0].x() == Approx(2.0).margin(1e-6));  // the pole itself
}

TEST_CASE("depth_matching in a sensor library: the window's angle and the disparity scale",
          "[sim][io]") {
  // 12 px of a 320-px image spanning 60 deg: 12 x 60 / 320 = 2.25 deg; focal length
  // 160 / tan(30 deg) = 277.13 px, baseline 0.05 m: 13.856 m px.
  test::TempFolder folder;
  std::string text = test::kLibrary;
  const std::string at = "        range: {min: 0.1, max: 4.0}\n";
  text.replace(text.find(at), 0,
               "        depth_matching: {window_px: 12, image_width_px: 320, baseline_m: 0.05, "
               "source: test}\n");
  const model::SensorLibrary library = io::load_sensor_library(folder.write("sensors.yaml", text));
  const model::SensorMode& mode = library.resolved_mode("cam", "m30");
  REQUIRE(mode.depth_matching);
  CHECK(mode.depth_matching->window_px == 12);
  CHECK(mode.depth_matching->window_angle == Approx(model::deg_to_rad(2.25)).epsilon(1e-12));
  CHECK(mode.depth_matching->baseline_focal ==
        Approx(0.05 * 160.0 / std::tan(model::deg_to_rad(30.0))).epsilon(1e-12));
  // A window of 0 pixels is refused at its field, line and column.
  std::string zero = text;
  zero.replace(zero.find("window_px: 12"), 13, "window_px: 0");
  try {
    io::load_sensor_library(folder.write("zero.yaml", zero));
    FAIL("a 0-px window was accepted");
  } catch (const model::InputError& error) {
    const std::string message = error.what();
    CHECK(message.find("zero.yaml:11:") != std::string::npos);
    CHECK(message.find("window_px") != std::string::npos);
  }
}

TEST_CASE("depth matching on a native pixel grid: the thin pole vanishes from the whole frame",
          "[sim]") {
  // 90 x 90 pixels over 9 x 9 deg: 0.1 deg per pixel; a 0.9 deg window, whose third is 3
  // pixels, so the window's rays are the grid's own. The 5 mm pole at 2 m spans 0.14 deg, under
  // two pixels: no window row holds it in more than its centre column, so no pixel reports it.
  model::SensorMode mode;
  mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(9.0), model::deg_to_rad(9.0)));
  mode.angular_resolution_h = mode.fov.horizontal() / 90;
  mode.angular_resolution_v = mode.fov.vertical() / 90;
  mode.min_range = 0.5;
  mode.max_range = 4.0;
  model::DepthMatching matching = kinect_window();
  matching.window_angle = model::deg_to_rad(0.9);
  mode.depth_matching = matching;
  const std::vector<model::Vec3> rays = sim::ray_pattern(mode);
  REQUIRE(rays.size() == 90 * 90);
  const sim::RayCaster scene(pole_before_wall(0.005));
  const model::Pose3 T_world_sensor = camera_pose();
  sim::SimulationSettings settings = noiseless();
  std::mt19937_64 rng(1);
  const auto on_pole = [](const model::PointCloud& cloud) {
    return std::count_if(cloud.points.begin(), cloud.points.end(),
                         [](const model::Point3f& p) { return p.x() < 2.5f; });
  };
  const model::PointCloud matched =
      sim::simulate_frame(scene, mode, rays, T_world_sensor, settings, rng);
  CHECK(on_pole(matched) == 0);
  CHECK(matched.size() > 8000);  // the wall everywhere else, the pole's pixels included
  settings.depth_matching = false;
  const model::PointCloud own =
      sim::simulate_frame(scene, mode, rays, T_world_sensor, settings, rng);
  CHECK(on_pole(own) > 0);
}
