// Issue 34 item 3: nav2's collision monitor from the rig. Zone edges seen or not against hand
// geometry (a pyramid on a cylinder's face), zone sizes against the stopping-distance formula
// computed here from the datasheet's text (the RPLIDAR A1's 5.5 Hz, its 0.15 m minimum range,
// the cart's 0.6 x 0.4 m footprint), and `check --collision-monitor` failing with the arc and
// the setting's file:line.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "rigdesign/deploy/zone_visibility.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;
using Catch::Matchers::WithinAbs;

namespace {

// The cart (rigs/cart_two_scanners.yaml): footprint front at x = 0.3 m, front scanner at
// (0.5, 0, 0.2) m, RPLIDAR A1 at 5.5 Hz with a 0.15 m minimum range (sensors.yaml).
constexpr double kCartFront = 0.3;
constexpr double kScannerX = 0.5;
constexpr double kScannerMinRange = 0.15;
constexpr double kScannerHz = 5.5;
// nav2's defaults: controller_frequency 20 Hz, velocity_smoother max_decel 2.5 m/s^2.
constexpr double kCommandPeriod = 1.0 / 20.0;
constexpr double kDefaultDeceleration = 2.5;

// Stopping distance: react within two frame periods and one command period, then brake;
// rounded up to the centimetre as export states.
double stop_reach(double speed, double deceleration) {
  const double latency = 2.0 / kScannerHz + kCommandPeriod;
  const double reach = speed * latency + speed * speed / (2.0 * deceleration);
  return std::ceil(reach * 100.0 - 1e-9) / 100.0;
}

// A polygon's points as nav2 Jazzy's string or Humble's flat list.
std::vector<std::pair<double, double>> zone_points(const YAML::Node& points) {
  std::vector<double> numbers;
  if (points.IsScalar()) {
    // "[[x, y], ...]": the numbers between the brackets and commas. (No std::regex: GCC 12
    // warns inside it under the sanitizer build, and warnings are errors.)
    std::string text = points.Scalar();
    for (char& c : text)
      if (c == '[' || c == ']' || c == ',') c = ' ';
    std::istringstream words(text);
    for (double value; words >> value;) numbers.push_back(value);
  } else {
    for (const YAML::Node& n : points) numbers.push_back(n.as<double>());
  }
  std::vector<std::pair<double, double>> pairs;
  for (std::size_t i = 0; i + 1 < numbers.size(); i += 2)
    pairs.emplace_back(numbers[i], numbers[i + 1]);
  return pairs;
}

double max_x(const std::vector<std::pair<double, double>>& points) {
  double x = -1e9;
  for (const auto& p : points) x = std::max(x, p.first);
  return x;
}

YAML::Node monitor_parameters(const std::string& folder) {
  return YAML::LoadFile(folder + "/collision_monitor.yaml")["collision_monitor"]["ros__parameters"];
}

// The cart with its requirements' robot_speed replaced by `speed_line`, in `folder`.
std::string cart_with(const TempFolder& folder, const std::string& speed_line) {
  std::string requirements = file_text(source_path("rigs/requirements/cart_two_scanners.yaml"));
  const std::string old_line = "robot_speed: {max_speed: 0.5, max_travel_between_frames: 0.1}";
  requirements.replace(requirements.find(old_line), old_line.size(), speed_line);
  const std::string requirements_path = folder.write("req.yaml", requirements);
  std::string rig = file_text(source_path("rigs/cart_two_scanners.yaml"));
  const std::string old_ref = "requirements: requirements/cart_two_scanners.yaml";
  rig.replace(rig.find(old_ref), old_ref.size(), "requirements: req.yaml");
  return folder.write("cart.yaml", rig);
}

}  // namespace

TEST_CASE("zone visibility: a 90 x 90 deg pyramid on a cylinder's face sees |y| <= x - 0.2",
          "[deploy]") {
  // Body: cylinder r = 0.2, h = 0.3. Sensor at (0.2, 0, 0.15) looking ahead: a column at
  // (x, y) over z in [0, 0.3] meets the pyramid where x > 0.2 and |y| <= x - 0.2 (at z = 0.15
  // the vertical test always holds). Zone: x in [0.2, 1], y in [-0.3, 0.3]. Unseen: each side
  // from x = 0.2 to 0.5 (0.3 m), and the back edge x = 0.2 except where it lies within 5 mm
  // of the body (|y| <= sqrt(0.205^2 - 0.2^2) = 0.045 m).
  model::RobotBody body;
  body.radius = 0.2;
  body.height = 0.3;
  model::SensorMode mode;
  mode.id = "pyramid";
  mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(90), model::deg_to_rad(90)));
  mode.min_range = 0.0;
  mode.max_range = 10.0;
  mode.frequency = 10.0;
  const geometry::BodyOccluder occluder(body);
  const geometry::MountedFov ahead(mode, model::pose_from_xyz_rpy({0.2, 0, 0.15}, {0, 0, 0}),
                                   occluder, "");
  const geometry::MountedFov behind(
      mode, model::pose_from_xyz_rpy({-0.2, 0, 0.15}, {0, 0, model::deg_to_rad(180)}), occluder,
      "");
  const std::vector<model::Vec2> zone = {{0.2, -0.3}, {1.0, -0.3}, {1.0, 0.3}, {0.2, 0.3}};
  deploy::BodyOutline outline;
  outline.radius = 0.2;
  const deploy::ZoneVisibility seen = deploy::zone_visibility(
      zone, outline, {{&ahead, 0.0, 1.0}, {&behind, 0.0, 1.0}}, body.height);
  const double near_body = std::sqrt(0.205 * 0.205 - 0.2 * 0.2);
  const double step = deploy::kBoundaryStep;
  CHECK_THAT(seen.checked_boundary, WithinAbs(2.8 - 2 * near_body, 2 * step));
  REQUIRE(seen.unseen.size() == 2);
  double unseen = 0.0;
  for (const deploy::BoundaryArc& arc : seen.unseen) {
    CHECK_THAT(arc.length, WithinAbs(0.3 + (0.3 - near_body), 2 * step));
    unseen += arc.length;
    // Each arc runs between a side's x = 0.5 point and the back edge near the body.
    const model::Vec2 side = std::abs(arc.from.x() - 0.5) < 2 * step ? arc.from : arc.to;
    CHECK_THAT(side.x(), WithinAbs(0.5, 2 * step));
    CHECK_THAT(std::abs(side.y()), WithinAbs(0.3, 1e-12));
  }
  CHECK_THAT(seen.seen_boundary[0], WithinAbs(seen.checked_boundary - unseen, 1e-9));
  CHECK(seen.sees[0]);
  CHECK_FALSE(seen.sees[1]);  // it looks the other way
  CHECK(seen.seen_boundary[1] == 0.0);
  SECTION("a height band above the column sees nothing") {
    const deploy::ZoneVisibility above =
        deploy::zone_visibility(zone, outline, {{&ahead, 0.35, 1.0}}, body.height);
    CHECK_FALSE(above.sees[0]);
    CHECK_THAT(above.unseen.front().length, WithinAbs(seen.checked_boundary, 1e-9));
  }
}

TEST_CASE(
    "collision monitor: zones sized by v t + v^2 / 2a; a zone inside the scanner's minimum "
    "range fails check with the arc and its file:line",
    "[deploy]") {
  TempFolder folder;
  const std::string out = folder.path() + "/export";
  REQUIRE(run_cli({"export", source_path("rigs/cart_two_scanners.yaml"), "--to", out}).exit_code ==
          0);
  const std::string file = out + "/collision_monitor.yaml";
  const YAML::Node p = monitor_parameters(out);
  const double reach = stop_reach(0.5, kDefaultDeceleration);  // the cart's R5: 0.5 m/s
  const auto stop = zone_points(p["stop_zone"]["points"]);
  CHECK_THAT(max_x(stop), WithinAbs(kCartFront + reach, 1e-4));
  // The slowdown zone adds v t and the braking from v to v / 2.
  const double latency = 2.0 / kScannerHz + kCommandPeriod;
  const double slow = std::ceil((reach + 0.5 * latency + (0.25 - 0.0625) / 5.0) * 100 - 1e-9) / 100;
  CHECK_THAT(max_x(zone_points(p["slowdown_zone"]["points"])), WithinAbs(kCartFront + slow, 1e-4));
  CHECK(p["stop_zone"]["action_type"].as<std::string>() == "stop");
  CHECK(p["slowdown_zone"]["slowdown_ratio"].as<double>() == 0.5);
  // Only the front scanner sees the zones ahead.
  REQUIRE(p["stop_zone"]["sources_names"].size() == 1);
  CHECK(p["stop_zone"]["sources_names"][0].as<std::string>() == "front_lidar");

  // The stop zone's front edge, 0.06 m ahead of the scanner, lies inside its 0.15 m minimum
  // range where |y| < sqrt(0.15^2 - 0.06^2): that arc is unseen.
  const double ahead = kCartFront + reach - kScannerX;
  const double blind = 2 * std::sqrt(kScannerMinRange * kScannerMinRange - ahead * ahead);
  const CliResult result = run_cli({"check", source_path("rigs/cart_two_scanners.yaml"),
                                    "--collision-monitor", file, "--format", "json"});
  CHECK(result.exit_code == 1);
  const nlohmann::json report = nlohmann::json::parse(result.out);
  std::vector<nlohmann::json> d4;
  for (const nlohmann::json& r : report["files"][0]["requirements"])
    if (r["id"] == "D4") d4.push_back(r);
  REQUIRE(d4.size() == 2);
  const std::string text = file_text(file);
  // The stop zone fails at its points' line; the slowdown zone, farther out, is seen.
  CHECK(d4[0]["verdict"] == "fail");
  CHECK(d4[0]["field"] == "stop_zone.points");
  CHECK(d4[0]["file"] == file);
  CHECK(d4[0]["line"] ==
        line_of(text.substr(text.find("stop_zone:")), "points:") + line_of(text, "stop_zone:") - 1);
  CHECK_THAT(d4[0]["actual"].get<double>(), WithinAbs(blind, 2 * deploy::kBoundaryStep));
  CHECK(d4[0]["explanation"].get<std::string>().find("from (0.56, -0.13") != std::string::npos);
  CHECK(d4[1]["verdict"] == "pass");

  SECTION("at 1 m/s the zones reach past the minimum range: check passes") {
    const std::string fast = folder.path() + "/fast";
    REQUIRE(run_cli({"export", source_path("rigs/cart_two_scanners.yaml"), "--to", fast,
                     "--max-speed", "1"})
                .exit_code == 0);
    CHECK_THAT(max_x(zone_points(monitor_parameters(fast)["stop_zone"]["points"])),
               WithinAbs(kCartFront + stop_reach(1.0, kDefaultDeceleration), 1e-4));
    CHECK(run_cli({"check", source_path("rigs/cart_two_scanners.yaml"), "--collision-monitor",
                   fast + "/collision_monitor.yaml"})
              .exit_code == 0);
  }
}

TEST_CASE("collision monitor: robot_speed.deceleration sizes the zones, a negative one is refused",
          "[deploy]") {
  TempFolder folder;
  const std::string gentle = cart_with(
      folder, "robot_speed: {max_speed: 0.5, max_travel_between_frames: 0.1, deceleration: 0.5}");
  REQUIRE(run_cli({"export", gentle, "--to", folder.path() + "/out"}).exit_code == 0);
  CHECK_THAT(max_x(zone_points(monitor_parameters(folder.path() + "/out")["stop_zone"]["points"])),
             WithinAbs(kCartFront + stop_reach(0.5, 0.5), 1e-4));

  TempFolder bad_folder;
  const std::string speed =
      "robot_speed: {max_speed: 0.5, max_travel_between_frames: 0.1, deceleration: -1.0}";
  const std::string bad = cart_with(bad_folder, speed);
  const CliResult result = run_cli({"check", bad});
  CHECK(result.exit_code == 2);
  // file:line:col of the value, counted in the file's text.
  const std::string requirements = bad_folder.path() + "/req.yaml";
  const std::string text = file_text(requirements);
  const std::size_t value = text.find("-1.0");
  const std::size_t column = value - text.rfind('\n', value);
  CHECK(result.out.find(requirements + ":" + std::to_string(line_of(text, "-1.0")) + ":" +
                        std::to_string(column)) != std::string::npos);
  CHECK(result.out.find("robot_speed.deceleration") != std::string::npos);
}

TEST_CASE("collision monitor: Humble's spelling (flat points, max_points) checks like Jazzy's",
          "[deploy]") {
  TempFolder folder;
  for (const char* distro : {"humble", "jazzy"}) {
    const std::string out = folder.path() + "/" + distro;
    REQUIRE(run_cli({"export", source_path("rigs/cart_two_scanners.yaml"), "--to", out,
                     "--ros-distro", distro})
                .exit_code == 0);
  }
  const YAML::Node humble = monitor_parameters(folder.path() + "/humble");
  const YAML::Node jazzy = monitor_parameters(folder.path() + "/jazzy");
  // Humble declares points a double array: every element a YAML float; Jazzy a string.
  REQUIRE(humble["stop_zone"]["points"].IsSequence());
  for (const YAML::Node& n : humble["stop_zone"]["points"])
    CHECK(n.Scalar().find('.') != std::string::npos);
  REQUIRE(jazzy["stop_zone"]["points"].IsScalar());
  CHECK(zone_points(humble["stop_zone"]["points"]) == zone_points(jazzy["stop_zone"]["points"]));
  // Humble acts above max_points, Jazzy at min_points (nav2's defaults 3 and 4).
  CHECK(humble["stop_zone"]["max_points"].as<int>() + 1 ==
        jazzy["stop_zone"]["min_points"].as<int>());
  CHECK_FALSE(humble["stop_zone"]["sources_names"].IsDefined());
  CHECK_FALSE(humble["state_topic"].IsDefined());
  for (const char* distro : {"humble", "jazzy"}) {
    CHECK(run_cli({"check", source_path("rigs/cart_two_scanners.yaml"), "--collision-monitor",
                   folder.path() + "/" + distro + "/collision_monitor.yaml"})
              .exit_code == 1);
  }
}

TEST_CASE("collision monitor file: bad input names file:line:col and the key", "[deploy]") {
  TempFolder folder;
  REQUIRE(run_cli({"export", source_path("rigs/cart_two_scanners.yaml"), "--to", folder.path()})
              .exit_code == 0);
  const std::string good = file_text(folder.path() + "/collision_monitor.yaml");
  const auto broken = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    REQUIRE(text.find(from) != std::string::npos);
    text.replace(text.find(from), from.size(), to);
    const std::string path = folder.write("bad.yaml", text);
    const CliResult result =
        run_cli({"check", source_path("rigs/cart_two_scanners.yaml"), "--collision-monitor", path});
    CHECK(result.exit_code == 2);
    return std::pair{result.out, text};
  };
  SECTION("a misspelt key, with nav2's name suggested") {
    const auto [out, text] = broken("min_points:", "min_pionts:");
    CHECK(out.find("bad.yaml:" + std::to_string(line_of(text, "min_pionts"))) != std::string::npos);
    CHECK(out.find("did you mean 'min_points'") != std::string::npos);
  }
  SECTION("sources_names naming no observation source") {
    const auto [out, text] =
        broken("sources_names: [\"front_lidar\"]", "sources_names: [\"lidar\"]");
    CHECK(out.find("bad.yaml:" + std::to_string(line_of(text, "sources_names"))) !=
          std::string::npos);
    CHECK(out.find("no observation source") != std::string::npos);
  }
  SECTION("a polygon nav2 refuses (three corners)") {
    const std::size_t at = good.find("points: \"");
    const std::size_t end = good.find('\n', at);
    const auto [out, text] =
        broken(good.substr(at, end - at), "points: \"[[0.3, 0.2], [0.9, 0.0], [0.3, -0.2]]\"");
    CHECK(out.find("bad.yaml:" + std::to_string(line_of(text, "points:"))) != std::string::npos);
    CHECK(out.find("at least 4 corners") != std::string::npos);
  }
}
