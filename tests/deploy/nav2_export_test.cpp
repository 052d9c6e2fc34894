// Issue 14: the exported nav2 costmap file. Keys and nesting follow nav2's "Costmap 2D"
// configuration page (https://docs.nav2.org/configuration/packages/configuring-costmaps.html:
// <costmap>: <costmap>: ros__parameters: with plugins, footprint or robot_radius, and per
// layer its plugin and parameters; observation_sources names the sources, each a map with
// topic, data_type, marking, clearing, obstacle_max_range, ... as the ObstacleLayer and
// VoxelLayer pages list them).
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_writer.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// One scanner 0.2 m ahead of the axis at 0.3 m, max range 10 m; d = 2 m, area up to 1 m;
// one camera pitched 30 deg down at 0.5 m on the front of a 0.4 x 0.3 m box body.
const std::string kNav2Rig = R"(name: nav2 test
sensor_library: sensors.yaml
body:
  footprint: [[0.2, 0.15], [-0.2, 0.15], [-0.2, -0.15], [0.2, -0.15]]
  height: 1.0
distance_of_interest: 2.0
mounts:
  - {id: scanner, sensor: scan2d, mode: m10, pose: {xyz: [0.2, 0, 0.3], rpy_deg: [0, 0, 0]}}
  - {id: cam, sensor: cam, mode: m30, pose: {xyz: [0.21, 0, 0.5], rpy_deg: [0, 30, 0]}}
)";

const std::string kScanner = R"(
  - id: scan2d
    name: Scanner
    technology: lidar_2d
    source: test datasheet
    price: {usd: 500, year: 2020, basis: estimate, source: test}
    modes:
      - id: m10
        fov: {shape: planar, horizontal_deg: 270, beam_divergence_deg: 0.5}
        range: {min: 0.05, max: 10.0}
        frequency: 10
        angular_resolution_deg: [0.5]
        points_per_frame: 541
        bytes_per_point: 4
        noise: {a: 0.03}
        light: {dark: true, indoor: true, sunlight: true}
        driver_cpu: {cores: 0.05, basis: estimate}
)";

}  // namespace

TEST_CASE("export: nav2 parameters read back give the sources, footprint and layers", "[deploy]") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary + kScanner);
  const model::Rig rig = io::load_rig(folder.write("rig.yaml", kNav2Rig));
  const model::SensorLibrary library = io::load_sensor_library(folder.path() + "/sensors.yaml");
  const deploy::Deployment deployment = deploy::plan_deployment(rig, library, nullptr, {});
  const std::string path =
      folder.write("nav2.yaml", deploy::nav2_costmap_text(deployment.costmap, "test"));
  const deploy::CostmapParamsFile file = deploy::load_costmap_params(path, {}, {});
  REQUIRE(file.sources.size() == 2);
  CHECK(file.sources[0].name == "scanner");
  CHECK(file.sources[1].name == "cam");
  for (std::size_t i = 0; i < 2; ++i)
    CHECK(file.sources[i].source == deployment.costmap.sources[i].source);
  // Hand-derived: the scanner must mark up to the area's far corner from its origin,
  // hypot(d + 0.2, max(0.3, 1.0 - 0.3)) = hypot(2.2, 0.7) = 2.3087 -> 2.31 m (cm up), well
  // inside its 10 m; it clears 0.5 m further; its blind zone (0.05 m) is neither marked nor
  // cleared. The band tops at the area's 1.0 m.
  const costmap::ObservationSource& scanner = file.sources[0].source;
  CHECK(scanner.obstacle_max_range == Approx(2.31));
  CHECK(scanner.raytrace_max_range == Approx(2.81));
  CHECK(scanner.obstacle_min_range == Approx(0.05));
  CHECK(scanner.raytrace_min_range == Approx(0.05));
  CHECK(scanner.max_obstacle_height == Approx(1.0));
  // A level scanner sees no floor: min_obstacle_height is the floor flatness (0.02 m) alone.
  CHECK(scanner.min_obstacle_height == Approx(0.02));
  // The camera (60 x 40 deg, pitched 30 deg down) has its steepest ray 50 deg down: it sees
  // the floor from 0.5 / sin 50 deg = 0.6527 m along the ray; sigma = 0.01 m, so a floor
  // return errs by at most 0.01 sin 50 deg = 0.00766 m in height: 0.02 + 6 x 0.00766 =
  // 0.0660 -> 0.07 m. Its reach: hypot(2.21, max(0.5, 0.5)) = 2.2659, capped by its 4 m.
  const costmap::ObservationSource& cam = file.sources[1].source;
  CHECK(cam.min_obstacle_height == Approx(0.07));
  CHECK(cam.obstacle_max_range == Approx(2.27));
  // The box body: its hull is the footprint itself; circumscribed radius hypot(0.2, 0.15) =
  // 0.25, inscribed 0.15 (nav2 derives both from the polygon).
  REQUIRE(file.footprint.size() == 4);
  CHECK(file.costmap.robot_radius == Approx(0.25));
  CHECK(file.costmap.inflation.inscribed_radius == Approx(0.15));
  CHECK(file.costmap.inflation.inflation_radius == Approx(0.35));
  // A camera is 3D: the voxel layer, 1 m in 16 voxels at most -> 0.07 m x 15.
  CHECK(file.costmap.layer == costmap::ObstacleLayerKind::voxel);
  CHECK(file.costmap.voxel.z_resolution == Approx(0.07));
  CHECK(file.costmap.voxel.z_max == Approx(1.05));
  // No Hit Layer unless asked for (export --hit-layer-plugin): nav2 has none.
  CHECK_FALSE(file.costmap.use_hit_layer);
}

TEST_CASE("export: nav2 names in the exported file", "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path("rigs/turtlebot4.yaml"));
  const std::string text =
      deploy::nav2_costmap_text(deploy::plan_deployment(rig, library, nullptr, {}).costmap, "test");
  for (const std::string key :
       {"local_costmap:\n  local_costmap:\n    ros__parameters:\n",
        "global_costmap:\n  global_costmap:\n    ros__parameters:\n",
        "plugin: \"nav2_costmap_2d::VoxelLayer\"", "plugin: \"nav2_costmap_2d::InflationLayer\"",
        "plugin: \"nav2_costmap_2d::StaticLayer\"", "observation_sources: lidar oakd",
        "data_type: \"LaserScan\"", "data_type: \"PointCloud2\"",
        // The description's own optical child of the link the OAK-D is placed on.
        "sensor_frame: oakd_rgb_camera_optical_frame", "robot_base_frame: base_link"}) {
    INFO(key);
    CHECK(text.find(key) != std::string::npos);
  }
}

// `export --update-rate` sizes the Hit Layer for a rate, so the costmap must run at that rate:
// the file's local update_frequency is the option's value, written as a double (rclcpp refuses
// an integer for nav2's double parameter). Read with yaml-cpp, not rigdesign's reader.
TEST_CASE("export: --update-rate reaches the local costmap's update_frequency", "[deploy]") {
  TempFolder folder;
  for (const auto& [rate, text] : {std::pair{"12.5", "12.5"}, {"10", "10.0"}}) {
    INFO(rate);
    const std::string out = folder.path() + "/rate_" + rate;
    const CliResult result = run_cli(
        {"export", source_path("rigs/turtlebot4.yaml"), "--to", out, "--update-rate", rate});
    INFO(result.err);
    REQUIRE(result.exit_code == 0);
    const YAML::Node file = YAML::LoadFile(out + "/nav2_costmap.yaml");
    const YAML::Node local = file["local_costmap"]["local_costmap"]["ros__parameters"];
    CHECK(local["update_frequency"].as<double>() == std::stod(rate));
    CHECK(local["update_frequency"].Scalar() == text);
    CHECK(file["global_costmap"]["global_costmap"]["ros__parameters"]["update_frequency"]
              .as<double>() == 1.0);
  }
}
