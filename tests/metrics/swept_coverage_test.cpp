// Issue 38 item 4: swept coverage, by hand. Every rig here stands its sensor on the robot's axis
// at z = 0.4, above a 0.2 m x 0.3 m cylinder, inside an area 0.5 m high: a column at (rho,
// theta) is then seen exactly when theta is inside the sensor's horizontal aperture and rho
// within its range (the sensor's own height is inside every column, the body is below its
// rays), so the times below follow from angles and circles alone.
//
// Turning in place, a 220 deg scanner is blind in (110, 250) deg. A point straight behind
// (180 deg) at 1 m is at robot azimuth 180 - psi after a left turn of psi (180 + psi to the
// right), and is first seen when that reaches 110 deg: after 70 deg. The last world azimuth of
// the blind sector, 250 deg, needs 140 deg. The header's bound: an azimuth edge to within half
// the azimuth step, and the first sample after it up to one time step later.
#include "rigdesign/metrics/swept_coverage.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

std::string swept_mode(const std::string& id, const std::string& fov, double max_range,
                       const std::string& resolution = "[0.5]") {
  return "      - id: " + id + "\n        fov: " + fov +
         "\n        range: {min: 0.05, max: " + std::to_string(max_range) +
         "}\n        frequency: 10\n        angular_resolution_deg: " + resolution +
         "\n"
         "        points_per_frame: 720\n        bytes_per_point: 4\n        noise: {a: 0.01}\n"
         "        light: {dark: true, indoor: true, sunlight: true}\n"
         "        driver_cpu: {cores: 0.05, basis: estimate}\n";
}

std::string swept_sensor(const std::string& id, const std::string& technology,
                         const std::string& mode) {
  return "  - id: " + id + "\n    name: " + id + "\n    technology: " + technology +
         "\n    source: test datasheet\n"
         "    price: {usd: 100, year: 2020, basis: estimate, source: test}\n    modes:\n" +
         mode;
}

// A 220 and a 360 deg scanner (10 m), and a 90 x 60 deg camera that sees only to 0.6 m.
const std::string kSweptLibrary =
    "reference_machine: test machine\nsensors:\n" +
    swept_sensor(
        "scan220", "lidar_2d",
        swept_mode("m", "{shape: planar, horizontal_deg: 220, beam_divergence_deg: 1}", 10.0)) +
    swept_sensor(
        "scan360", "lidar_2d",
        swept_mode("m", "{shape: planar, horizontal_deg: 360, beam_divergence_deg: 1}", 10.0)) +
    swept_sensor("cam90", "tof",
                 swept_mode("m", "{shape: pyramid, horizontal_deg: 90, vertical_deg: 60}", 0.6,
                            "[0.5, 0.5]"));

std::string swept_rig(const std::string& sensor, double distance) {
  return "name: Swept case\nbody: {radius: 0.2, height: 0.3}\narea_height: 0.5\n"
         "distance_of_interest: " +
         std::to_string(distance) + "\nmounts:\n  - {id: s, sensor: " + sensor +
         ", mode: m, pose: {xyz: [0, 0, 0.4], rpy_deg: [0, 0, 0]}}\n";
}

struct SweptCase {
  test::TempFolder folder;
  model::SensorLibrary library;
  model::Rig rig;
  SweptCase(const std::string& sensor, double distance)
      : library(io::load_sensor_library(folder.write("sensors.yaml", kSweptLibrary))),
        rig(io::load_rig(folder.write("rig.yaml", swept_rig(sensor, distance)))) {}
};

const metrics::SweepCell& swept_cell_at(const metrics::SweepRun& run, double x, double y) {
  for (const metrics::SweepCell& cell : run.cells) {
    if ((cell.centre - model::Vec2(x, y)).norm() < 1e-9) return cell;
  }
  FAIL("no cell centred at " << x << ", " << y);
  return run.cells.front();
}

}  // namespace

TEST_CASE("swept: a 220 deg scanner turning in place sees behind after 70 deg",
          "[metrics][swept]") {
  const SweptCase input("scan220", 1.5);
  constexpr double kOmega = 1.0;  // [rad/s]
  metrics::SweepMotion motion;
  motion.turn_rate = kOmega;
  metrics::SweepSettings settings;
  settings.horizon = metrics::default_horizon(motion, 1.5);
  CHECK(settings.horizon == Approx(2 * std::numbers::pi));  // one full turn
  const metrics::SweptCoverage sweep =
      metrics::swept_coverage(input.rig, input.library, motion, settings);
  REQUIRE(sweep.runs.size() == 2);
  // The stated bounds hold: a cell 1.5 m out moves under half a 5 cm cell, the turn under
  // half a degree between samples.
  CHECK(sweep.time_step * kOmega * 1.5 <= 0.025 + 1e-12);
  CHECK(sweep.time_step * kOmega <= sweep.azimuth_step / 2 + 1e-12);

  const double early = (model::deg_to_rad(70.0) - sweep.azimuth_step / 2) / kOmega;
  // Inclusive bounds: the sample at +-110 deg lies on the aperture's edge plane and counts on
  // one side only, so one direction may meet the upper bound exactly (1e-9 s of rounding).
  const double late =
      (model::deg_to_rad(70.0) + sweep.azimuth_step / 2) / kOmega + sweep.time_step + 1e-9;
  for (const metrics::SweepRun& run : sweep.runs) {
    INFO("turn rate " << run.motion.turn_rate);
    const metrics::SweepCell& behind = swept_cell_at(run, -1.0, 0.0);
    REQUIRE(behind.first_seen);
    CHECK(*behind.first_seen >= early);
    CHECK(*behind.first_seen <= late);
    // Straight ahead is seen at once; everything after the blind sector's 140 deg, give or
    // take the grid's angular spacing at 1.5 m (5 cm / 1.5 m = 1.9 deg) and the bound above.
    CHECK(swept_cell_at(run, 1.0, 0.0).first_seen == 0.0);
    REQUIRE(run.all_seen_time);
    CHECK(*run.all_seen_time * kOmega <= model::deg_to_rad(140.0 + 0.5) + sweep.time_step);
    CHECK(*run.all_seen_time * kOmega >= model::deg_to_rad(140.0 - 1.91 - 0.5));
    CHECK(run.seen_share == 1.0);
    // A cylinder turning in place runs into nothing.
    CHECK(run.swept == 0);
    CHECK(run.late == 0);
  }
  // The rig is symmetric: both directions see behind within the bound's width of each other.
  CHECK(std::abs(*swept_cell_at(sweep.runs[0], -1.0, 0.0).first_seen -
                 *swept_cell_at(sweep.runs[1], -1.0, 0.0).first_seen) <=
        sweep.azimuth_step / kOmega + sweep.time_step + 1e-9);
  CHECK(sweep.pass());
}

TEST_CASE("swept: a 360 deg scanner sees every cell at once", "[metrics][swept]") {
  const SweptCase input("scan360", 1.5);
  metrics::SweepMotion motion;
  motion.turn_rate = 0.5;
  metrics::SweepSettings settings;
  settings.horizon = 1.0;
  const metrics::SweptCoverage sweep =
      metrics::swept_coverage(input.rig, input.library, motion, settings);
  for (const metrics::SweepRun& run : sweep.runs) {
    // Cells of 5 cm within 1.5 m and outside the 0.2 m body: about pi (1.5^2 - 0.2^2) / 0.05^2.
    CHECK(run.cells.size() ==
          Approx(std::numbers::pi * (1.5 * 1.5 - 0.2 * 0.2) / 0.0025).epsilon(0.02));
    for (const metrics::SweepCell& cell : run.cells) {
      REQUIRE(cell.first_seen);
      CHECK(*cell.first_seen == 0.0);
    }
    REQUIRE(run.all_seen_time);
    CHECK(*run.all_seen_time == 0.0);
  }
}

// Driving a left arc of R = 1 m at 0.5 m/s with the camera that sees 0.6 m. The cell at (1, 1)
// lies on the arc a quarter turn ahead (alpha = 90 deg about the arc's centre (0, 1)); after
// the robot turns psi its distance is 2 R sin(alpha / 2), alpha = 90 deg - psi, at bearing
// alpha / 2 (inside the camera's 45 deg). Seen from 0.6 m: alpha = 2 asin(0.3) = 34.915 deg,
// psi = 55.085 deg = 0.96142 rad, t = psi R / v = 1.92284 s. Reached when the body's outline
// touches a 0.1 m obstacle there, 0.2 + 0.05 m from the axis: alpha = 2 asin(0.125) =
// 14.362 deg, psi = 75.638 deg = 1.32014 rad, t = 2.64029 s. Warned 0.71745 s ahead.
TEST_CASE("swept: a forward camera on an arc sees a cell in the path too late to stop",
          "[metrics][swept]") {
  const SweptCase input("cam90", 2.0);
  metrics::SweepMotion motion;
  motion.kind = metrics::SweepKind::arc;
  motion.arc_radius = 1.0;
  motion.speed = 0.5;
  metrics::SweepSettings settings;
  settings.horizon = metrics::default_horizon(motion, 2.0);
  CHECK(settings.horizon == Approx(4.0));  // d / v
  settings.cell = 0.1;
  const double seen = (std::numbers::pi / 2 - 2 * std::asin(0.3)) * 1.0 / 0.5;
  const double reached = (std::numbers::pi / 2 - 2 * std::asin(0.125)) * 1.0 / 0.5;
  CHECK(seen == Approx(1.92284).margin(1e-5));
  CHECK(reached == Approx(2.64029).margin(1e-5));

  SECTION("braking at 0.5 m/s^2 needs 1 s of warning: late") {
    settings.deceleration = 0.5;
    const metrics::SweptCoverage sweep =
        metrics::swept_coverage(input.rig, input.library, motion, settings);
    REQUIRE(sweep.runs.size() == 1);
    CHECK(sweep.stopping_time == Approx(1.0));
    const metrics::SweepRun& run = sweep.worst_run();
    const metrics::SweepCell& cell = swept_cell_at(run, 1.0, 1.0);
    REQUIRE(cell.first_seen);
    REQUIRE(cell.reached);
    // The first sample at or after each time; 1 mm of tessellation at the range's end.
    CHECK(*cell.first_seen >= seen - 0.002);
    CHECK(*cell.first_seen <= seen + sweep.time_step + 0.002);
    CHECK(*cell.reached >= reached);
    CHECK(*cell.reached <= reached + sweep.time_step);
    CHECK(cell.late);
    CHECK(run.late > 0);
    REQUIRE(run.worst_late);
    CHECK_FALSE(sweep.pass());
  }
  SECTION("braking at 2.5 m/s^2 needs 0.2 s: in time") {
    settings.deceleration = 2.5;
    const metrics::SweptCoverage sweep =
        metrics::swept_coverage(input.rig, input.library, motion, settings);
    CHECK(sweep.stopping_time == Approx(0.2));
    CHECK_FALSE(swept_cell_at(sweep.worst_run(), 1.0, 1.0).late);
  }
}

TEST_CASE("swept: the motion's poses", "[metrics][swept]") {
  metrics::SweepMotion arc;
  arc.kind = metrics::SweepKind::arc;
  arc.arc_radius = -2.0;  // a right turn: the centre at (0, -2)
  arc.speed = 1.0;
  // A quarter of the circle: pi m at 1 m/s puts the robot at (2, -2), heading -90 deg.
  const metrics::SweepPose quarter = arc.pose_at(std::numbers::pi);
  CHECK(quarter.position.x() == Approx(2.0));
  CHECK(quarter.position.y() == Approx(-2.0));
  CHECK(quarter.heading == Approx(-std::numbers::pi / 2));
  model::RobotBody body;
  body.radius = 0.25;
  CHECK(metrics::rim_turn_rate(0.5, body) == Approx(2.0));
}

TEST_CASE("swept: --sweep refuses what it cannot read", "[metrics][swept][cli]") {
  const std::string rig = test::source_path("rigs/turtlebot4.yaml");
  for (const std::string bad : {"spin", "arc:abc", "arc:0", "arc:", "arc:nan", "arc:inf"}) {
    INFO(bad);
    const test::CliResult result = test::run_cli({"coverage", rig, "--sweep", bad});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("--sweep") != std::string::npos);
    CHECK(result.err.find("rotate or arc:R") != std::string::npos);
  }
}

TEST_CASE("swept: an arc needs the requirements' robot speed", "[metrics][swept][cli]") {
  const SweptCase input("cam90", 2.0);
  const test::CliResult result = test::run_cli(
      {"coverage", input.folder.path() + "/rig.yaml", "--sweep", "arc:0.8", "--no-3d"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--sweep") != std::string::npos);
  CHECK(result.err.find("robot_speed") != std::string::npos);
}
