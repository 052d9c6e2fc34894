// Issue 14 item 2: `check --nav2 --filters` guards the configuration a rig is deployed with.
#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <string>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

// The cart's rear scanner faces backwards (yaw 180 deg): its own +-0.8 rad is the robot's
// rear, the whole back sector (150..210 deg of the robot is -30..30 deg of the scanner).
const std::string kHidesRear = R"(rear_lidar_self_filter:
  ros__parameters:
    filter1:
      name: hides_the_rear
      type: laser_filters/LaserScanAngularBoundsFilterInPlace
      params:
        lower_angle: -0.8
        upper_angle: 0.8
)";

// The same filter narrowed to where the scanner sees the cart itself: the corners of the back
// face are at +-135 deg seen from the scanner (0.2 m behind a 0.4 m wide face), so
// |angle| > 2.356 rad; in-place bounds from 2.36 rad through pi, written as two bands.
const std::string kBodyOnly = R"(rear_lidar_self_filter:
  ros__parameters:
    filter1:
      name: body_left
      type: laser_filters/LaserScanAngularBoundsFilterInPlace
      params: {lower_angle: 2.36, upper_angle: 3.2}
    filter2:
      name: body_right
      type: laser_filters/LaserScanAngularBoundsFilterInPlace
      params: {lower_angle: -3.2, upper_angle: -2.36}
)";

}  // namespace

TEST_CASE("check --filters: a filter hiding a required sector fails at its line", "[deploy]") {
  TempFolder folder;
  const std::string cart = source_path("rigs/cart_two_scanners.yaml");
  const CliResult hides =
      run_cli({"check", cart, "--filters", folder.write("hides.yaml", kHidesRear)});
  INFO(hides.out << hides.err);
  CHECK(hides.exit_code == 1);
  // The filter's entry is on line 3 of the file ("filter1:" at column 5).
  CHECK(hides.out.find(folder.path() +
                       "/hides.yaml:3:5: sectors: fail: D3 deployed coverage: back") !=
        std::string::npos);
  CHECK(hides.out.find("rear_lidar hides_the_rear drops (-0.8, 0.8) rad") != std::string::npos);
  const CliResult narrowed =
      run_cli({"check", cart, "--filters", folder.write("body.yaml", kBodyOnly)});
  INFO(narrowed.out << narrowed.err);
  CHECK(narrowed.exit_code == 0);
  // The exported files pass too, and their filters drop only the robot: no warning.
  const std::string out = folder.path() + "/export";
  REQUIRE(run_cli({"export", cart, "--to", out}).exit_code == 0);
  const CliResult exported = run_cli({"check", cart, "--nav2", out + "/nav2_costmap.yaml",
                                      "--filters", out + "/self_filters.yaml"});
  INFO(exported.out << exported.err);
  CHECK(exported.exit_code == 0);
  CHECK(exported.out.find("D1 observation source for rear_lidar") != std::string::npos);
  // The one warning is about the rig, not its deployment: the two scanners light each other
  // and sensors.yaml has no vendor statement on RPLIDAR crosstalk (issue 38).
  const std::size_t warning = exported.out.find("warning");
  REQUIRE(warning != std::string::npos);
  const std::size_t crosstalk = exported.out.find(
      "front_lidar (rplidar_a1m8) and rear_lidar (rplidar_a1m8) light each other");
  CHECK(crosstalk != std::string::npos);
  CHECK(crosstalk > warning);
  CHECK(exported.out.find("warning", warning + 1) == std::string::npos);
}

TEST_CASE("check --nav2: a range limit that opens a blind ring fails, a missing source fails",
          "[deploy]") {
  TempFolder folder;
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  const std::string out = folder.path() + "/export";
  REQUIRE(run_cli({"export", rig, "--to", out}).exit_code == 0);
  std::string text;
  {
    std::ifstream in(out + "/nav2_costmap.yaml");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const CliResult exported = run_cli({"check", rig, "--nav2", out + "/nav2_costmap.yaml"});
  CHECK(exported.exit_code == 0);
  // The mower of the issue: obstacle_min_range raised to hide something near the robot. The
  // Azure Kinect's first floor return is 0.89 m from its lens (0.75 m high, floor seen from
  // 0.48 m ahead), so 1.2 m leaves a blind ring in front.
  const std::string key = "obstacle_min_range: 0.5  #";
  REQUIRE(text.find(key) != std::string::npos);
  std::string mower = text;
  mower.replace(mower.find(key), key.size(), "obstacle_min_range: 1.2  #");
  const CliResult ring = run_cli({"check", rig, "--nav2", folder.write("mower.yaml", mower)});
  INFO(ring.out << ring.err);
  CHECK(ring.exit_code == 1);
  // The finding is at the changed value: its line in the file's text, column 31 (10 spaces and
  // "obstacle_min_range: " before it).
  const std::string line = std::to_string(
      1 +
      std::count(mower.begin(),
                 mower.begin() + static_cast<std::ptrdiff_t>(mower.find("obstacle_min_range: 1.2")),
                 '\n'));
  CHECK(ring.out.find("mower.yaml:" + line + ":31: sectors: fail: D3 deployed coverage: front") !=
        std::string::npos);
  CHECK(ring.out.find("front_camera obstacle_min_range 1.2 m") != std::string::npos);
  // The top lidar left out of the sources: the costmap never sees it.
  const std::string listed =
      "observation_sources: front_camera left_camera right_camera back_camera top_lidar";
  REQUIRE(text.find(listed) != std::string::npos);
  std::string without = text;
  without.replace(without.find(listed), listed.size(),
                  "observation_sources: front_camera left_camera right_camera back_camera");
  const std::size_t block = without.find("        top_lidar:\n");
  without.erase(block, without.find("      inflation_layer:", block) - block);
  const CliResult missing =
      run_cli({"check", rig, "--nav2", folder.write("without.yaml", without)});
  INFO(missing.out << missing.err);
  CHECK(missing.exit_code == 1);
  CHECK(missing.out.find("fail: D1 observation source for top_lidar") != std::string::npos);
}

TEST_CASE("check --nav2 / --filters: bad files exit 2 naming file:line:col and the key",
          "[deploy]") {
  TempFolder folder;
  const std::string cart = source_path("rigs/cart_two_scanners.yaml");
  const auto nav2 = [&](const std::string& layers) {
    return "local_costmap:\n  local_costmap:\n    ros__parameters:\n"
           "      robot_radius: 0.36\n" +
           layers;
  };
  // A listed layer without its plugin class.
  const CliResult plugin =
      run_cli({"check", cart, "--nav2",
               folder.write("plugin.yaml",
                            nav2("      plugins: [\"obstacle_layer\"]\n      obstacle_layer:\n"
                                 "        observation_sources: front_lidar\n"
                                 "        front_lidar: {data_type: LaserScan}\n"))});
  CHECK(plugin.exit_code == 2);
  CHECK(plugin.out.find("plugin.yaml:7:9") != std::string::npos);
  CHECK(plugin.out.find("has no plugin") != std::string::npos);
  // A source named after no mount.
  const CliResult source =
      run_cli({"check", cart, "--nav2",
               folder.write("source.yaml", nav2("      obstacle_layer:\n        plugin: x\n"
                                                "        observation_sources: bumper\n"
                                                "        bumper: {data_type: LaserScan}\n"))});
  CHECK(source.exit_code == 2);
  CHECK(source.out.find("source.yaml:8:17: bumper") != std::string::npos);
  CHECK(source.out.find("names no mount") != std::string::npos);
  // A negative range.
  const CliResult negative =
      run_cli({"check", cart, "--nav2",
               folder.write("negative.yaml", nav2("      obstacle_layer:\n        plugin: x\n"
                                                  "        observation_sources: front_lidar\n"
                                                  "        front_lidar:\n"
                                                  "          raytrace_min_range: -1\n"))});
  CHECK(negative.exit_code == 2);
  CHECK(negative.out.find("negative.yaml:9:31") != std::string::npos);
  CHECK(negative.out.find("raytrace_min_range: is negative") != std::string::npos);
  // A filter file for a sensor the rig lacks.
  const CliResult lacks =
      run_cli({"check", cart, "--filters",
               folder.write("lacks.yaml",
                            "top_lidar_self_filter:\n  ros__parameters:\n    filter1:\n"
                            "      type: laser_filters/LaserScanRangeFilter\n"
                            "      params: {lower_threshold: 0.3}\n")});
  CHECK(lacks.exit_code == 2);
  CHECK(lacks.out.find("lacks.yaml:1:1: top_lidar_self_filter") != std::string::npos);
  CHECK(lacks.out.find("names no mount") != std::string::npos);
  // Degrees in a radians field (issue 30, item 7): -135.1 is beyond -2 pi, so not a scan angle.
  const CliResult degrees =
      run_cli({"check", cart, "--filters",
               folder.write("degrees.yaml",
                            "rear_lidar_self_filter:\n  ros__parameters:\n    filter1:\n"
                            "      type: laser_filters/LaserScanAngularBoundsFilterInPlace\n"
                            "      params: {lower_angle: -135.1, upper_angle: 135.1}\n")});
  INFO(degrees.out);
  CHECK(degrees.exit_code == 2);
  // "lower_angle: -135.1" starts at column 16 of line 5; the value at column 29.
  CHECK(degrees.out.find("degrees.yaml:5:29: ") != std::string::npos);
  CHECK(degrees.out.find("lower_angle: looks like degrees") != std::string::npos);
  CHECK(degrees.out.find("-2.358 rad") != std::string::npos);  // -135.1 deg in radians
}

TEST_CASE("check --nav2: a layer class outside nav2 and STVL warns, an undeclared key fails",
          "[deploy]") {
  TempFolder folder;
  const std::string cart = source_path("rigs/cart_two_scanners.yaml");
  const auto nav2 = [&](const std::string& plugin, const std::string& source_extra) {
    return "local_costmap:\n  local_costmap:\n    ros__parameters:\n"
           "      robot_radius: 0.36\n"
           "      plugins: [\"obstacle_layer\", \"hit_layer\"]\n"
           "      obstacle_layer:\n"
           "        plugin: \"nav2_costmap_2d::ObstacleLayer\"\n"
           "        observation_sources: front_lidar rear_lidar\n"
           "        front_lidar: {data_type: LaserScan" +
           source_extra +
           "}\n"
           "        rear_lidar: {data_type: LaserScan}\n"
           "      hit_layer:\n"
           "        plugin: \"" +
           plugin + "\"\n";
  };
  // nav2's own and STVL's classes pass without a word.
  const CliResult stvl =
      run_cli({"check", cart, "--nav2",
               folder.write("stvl.yaml",
                            nav2("spatio_temporal_voxel_layer/SpatioTemporalVoxelLayer", ""))});
  INFO(stvl.out << stvl.err);
  CHECK(stvl.exit_code == 0);
  // (The rig's own findings, such as its two lidars' crosstalk, may still be printed.)
  CHECK(stvl.out.find("warning: hit_layer") == std::string::npos);
  CHECK(stvl.out.find("hit_layer.plugin: names") == std::string::npos);
  // Any other class: nav2 cannot load it unless the user built it. "plugin:" of hit_layer is on
  // line 12, its value at column 17 (8 spaces and "plugin: " before it).
  const CliResult hit =
      run_cli({"check", cart, "--nav2", folder.write("hit.yaml", nav2("rigdesign::HitLayer", ""))});
  INFO(hit.out << hit.err);
  CHECK(hit.exit_code == 0);
  CHECK(hit.out.find("hit.yaml:12:17: warning: hit_layer.plugin: names") != std::string::npos);
  // ROS 1's obstacle_range is not a nav2 parameter: nav2 would ignore it without a word.
  const CliResult ros1 = run_cli(
      {"check", cart, "--nav2",
       folder.write("ros1.yaml", nav2("nav2_costmap_2d::DenoiseLayer", ", obstacle_range: 2.5"))});
  INFO(ros1.out << ros1.err);
  CHECK(ros1.exit_code == 2);
  // Line 9: 8 spaces, "front_lidar: {" and "data_type: LaserScan, " put the key at column 45.
  CHECK(ros1.out.find("ros1.yaml:9:45: ") != std::string::npos);
  CHECK(ros1.out.find("obstacle_range") != std::string::npos);
}

TEST_CASE("check --filters: a filter removing more than the robot warns even when D3 passes",
          "[deploy]") {
  TempFolder folder;
  const std::string cart = source_path("rigs/cart_two_scanners.yaml");
  // The cart's requirements with nothing asked of the back: hiding it passes D3 (0 >= 0).
  const std::string relaxed =
      folder.write("relaxed.yaml",
                   "name: cart, back not required\n"
                   "sectors:\n"
                   "  - {name: front, from_deg: -30, to_deg: 30, min_complete_coverage: 0.04, "
                   "min_floor_coverage: 0}\n"
                   "  - {name: back, from_deg: 150, to_deg: 210, min_complete_coverage: 0, "
                   "min_floor_coverage: 0}\n"
                   "range: {distance: 3.0}\n");
  const CliResult hides = run_cli({"check", cart, "--requirements", relaxed, "--filters",
                                   folder.write("hides.yaml", kHidesRear)});
  INFO(hides.out << hides.err);
  CHECK(hides.exit_code == 0);
  CHECK(hides.out.find("pass: D3 deployed coverage: back") != std::string::npos);
  // At the filter's entry (line 3, column 5), naming it and the sector it takes.
  CHECK(hides.out.find("hides.yaml:3:5: warning: rear_lidar hides_the_rear drops (-0.8, 0.8) "
                       "rad: removes ") != std::string::npos);
  CHECK(hides.out.find("% of back (SC") != std::string::npos);
  // That the exported filters warn of nothing is checked with the cart's own requirements in
  // "a filter hiding a required sector fails at its line" (the same export, one run in CI).
}

// Issue 30 item 5: where odom stands at base_link height (Clearpath's 2D EKF: 0.0655 m on
// the Jackal), the height bands are written 0.0655 m lower, and read back with the same
// height they are the floor bands again; read as if odom were on the floor, the band would
// end 0.0655 m below the top of the area and D2 fails.
TEST_CASE("export / check --global-frame-height: bands in the global frame", "[deploy]") {
  TempFolder folder;
  const std::string jackal = source_path("rigs/jackal.yaml");
  const std::string floor = folder.path() + "/floor";
  const std::string odom = folder.path() + "/odom";
  REQUIRE(run_cli({"export", jackal, "--to", floor}).exit_code == 0);
  REQUIRE(run_cli({"export", jackal, "--to", odom, "--global-frame-height", "0.0655"}).exit_code ==
          0);
  const auto band_top = [](const std::string& file) {
    std::ifstream in(file);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::string key = "max_obstacle_height: ";
    const std::size_t at = text.find(key);
    REQUIRE(at != std::string::npos);
    return std::stod(text.substr(at + key.size()));
  };
  // The Jackal's area ends at 0.25 m (rigs/jackal.yaml area_height).
  CHECK(band_top(floor + "/nav2_costmap.yaml") == Approx(0.25));
  CHECK(band_top(odom + "/nav2_costmap.yaml") == Approx(0.25 - 0.0655));
  const std::string requirements =
      folder.write("needs.yaml", "name: band only\nrange: {distance: 3.0}\n");
  const CliResult right = run_cli({"check", jackal, "--requirements", requirements, "--nav2",
                                   odom + "/nav2_costmap.yaml", "--global-frame-height", "0.0655"});
  INFO(right.out << right.err);
  CHECK(right.exit_code == 0);
  const CliResult wrong = run_cli(
      {"check", jackal, "--requirements", requirements, "--nav2", odom + "/nav2_costmap.yaml"});
  CHECK(wrong.exit_code == 1);
  CHECK(wrong.out.find("fail: D2 height band") != std::string::npos);
}

TEST_CASE("check --nav2 / --filters on a rig without requirements reads the files (10)",
          "[deploy]") {
  const std::string rig = source_path("rigs/turtlebot4.yaml");  // names no requirements
  const CliResult missing = run_cli(
      {"check", rig, "--nav2", "/nonexistent/nav2.yaml", "--filters", "/nonexistent/filters.yaml"});
  CHECK(missing.exit_code == 2);
  CHECK((missing.out + missing.err).find("/nonexistent/nav2.yaml") != std::string::npos);
  TempFolder folder;
  REQUIRE(run_cli({"export", rig, "--to", folder.path()}).exit_code == 0);
  const CliResult deployed = run_cli({"check", rig, "--nav2", folder.path() + "/nav2_costmap.yaml",
                                      "--filters", folder.path() + "/self_filters.yaml"});
  INFO(deployed.out << deployed.err);
  CHECK(deployed.exit_code == 0);
  // D1 needs no requirements: one observation source per mount of the rig file (lidar, oakd).
  CHECK(deployed.out.find("pass: D1 observation source for lidar") != std::string::npos);
  CHECK(deployed.out.find("pass: D1 observation source for oakd") != std::string::npos);
}
