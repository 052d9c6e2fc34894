// Issue 38 items 2 and 3: where two mounts see the same points, and R9 calibration overlap.
// The analytic case: a 0.2 m cylinder body 0.3 m tall, the area to perceive up to 0.5 m, out to
// d = 2 m. A 360 deg planar scanner at 0.4 m (above the body, below the area's top) sees a
// point of every column of the annulus, so two of them share its whole area, pi (d^2 - r^2);
// the polar grid's columns sum to that exactly (the midpoint rule is exact for rho). A 179 deg
// scanner looking forward sees the columns at the sampled azimuths -89..89 deg: 179 of 360.
// Their scan planes are at different heights: they share columns, not points.
// One above the area's top (0.6 m) sees nothing of it.
#include "rigdesign/metrics/covisibility.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/calibration_overlap.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

const std::string kScanners = R"(reference_machine: test machine
sensors:
  - id: scan
    name: Scanner
    technology: lidar_2d
    source: test datasheet
    price: {usd: 100, year: 2020, basis: estimate, source: test}
    mode_defaults:
      range: {min: 0.05, max: 6.0}
      frequency: 10
      angular_resolution_deg: [0.5]
      points_per_frame: 720
      bytes_per_second: 10000
      noise: {a: 0.01}
      light: {dark: true, indoor: true, sunlight: false}
      driver_cpu: {cores: 0.01, basis: estimate}
    modes:
      - {id: full, fov: {shape: planar, horizontal_deg: 360, beam_divergence_deg: 0.5}}
      - {id: half, fov: {shape: planar, horizontal_deg: 179, beam_divergence_deg: 0.5}}
)";

std::string covisibility_rig(const std::string& mounts) {
  return "name: covisibility case\nbody: {radius: 0.2, height: 0.3}\narea_height: 0.5\n"
         "distance_of_interest: 2.0\nmounts:\n" +
         mounts;
}

const std::string kFull =
    "  - {id: a, sensor: scan, mode: full, pose: {xyz: [0, 0, 0.4], rpy_deg: [0, 0, 0]}}\n";
const std::string kFullToo =
    "  - {id: b, sensor: scan, mode: full, pose: {xyz: [0, 0, 0.45], rpy_deg: [0, 0, 0]}}\n";
const std::string kHalf =
    "  - {id: c, sensor: scan, mode: half, pose: {xyz: [0, 0, 0.35], rpy_deg: [0, 0, 0]}}\n";
const std::string kAbove =
    "  - {id: e, sensor: scan, mode: full, pose: {xyz: [0, 0, 0.6], rpy_deg: [0, 0, 0]}}\n";

}  // namespace

TEST_CASE("covisibility: shared columns of two scanners, by hand", "[metrics][covisibility]") {
  test::TempFolder folder;
  const model::SensorLibrary library =
      io::load_sensor_library(folder.write("sensors.yaml", kScanners));
  const model::Rig rig =
      io::load_rig(folder.write("rig.yaml", covisibility_rig(kFull + kFullToo + kHalf + kAbove)));
  const metrics::Covisibility overlap = metrics::covisibility(rig, library, 2.0);
  const double annulus = std::numbers::pi * (2.0 * 2.0 - 0.2 * 0.2);
  REQUIRE(overlap.pairs.size() == 6);  // (a,b) (a,c) (a,e) (b,c) (b,e) (c,e)
  CHECK(overlap.pairs[0].column_area == Approx(annulus).epsilon(1e-9));
  CHECK(overlap.pairs[1].column_area == Approx(annulus * 179.0 / 360.0).epsilon(1e-9));
  CHECK(overlap.pairs[2].column_area == 0.0);
  CHECK(overlap.pairs[3].column_area == Approx(annulus * 179.0 / 360.0).epsilon(1e-9));
  CHECK(overlap.pairs[5].column_area == 0.0);
  // Their planes are 5 cm apart and 0.5 deg thick (9 mm at 2 m): no point seen by both; and
  // scanners above the floor see none of it.
  CHECK(overlap.pairs[0].area == 0.0);
  CHECK(overlap.pairs[0].floor_area == 0.0);

  // R9: with 1 m^2 needed, e is cut off and named; the others are connected.
  model::CalibrationRequirement needed;
  needed.min_overlap = 1.0;
  const metrics::RequirementResult connected = metrics::calibration_verdict(rig, needed, overlap);
  CHECK(connected.id == "R9");
  CHECK(connected.verdict == metrics::Verdict::fail);
  CHECK(connected.limiting_mounts == std::vector<std::string>{"e"});
  CHECK(connected.rig_where.line == 9);  // e's entry: the fourth mount, line 9 of covisibility_rig
  CHECK(connected.explanation.find("cut off from the rest: e") != std::string::npos);
  // Without e every pair shares more than 1 m^2: `pairs: all` passes, and fails above the
  // half scanner's share.
  const model::Rig three =
      io::load_rig(folder.write("three.yaml", covisibility_rig(kFull + kFullToo + kHalf)));
  const metrics::Covisibility three_overlap = metrics::covisibility(three, library, 2.0);
  needed.all_pairs = true;
  CHECK(metrics::calibration_verdict(three, needed, three_overlap).verdict ==
        metrics::Verdict::pass);
  needed.min_overlap = annulus * 0.6;
  const metrics::RequirementResult all = metrics::calibration_verdict(three, needed, three_overlap);
  CHECK(all.verdict == metrics::Verdict::fail);
  CHECK(all.actual == Approx(annulus * 179.0 / 360.0).epsilon(1e-9));
}

TEST_CASE("calibration: a rear lidar sharing nothing with the front cameras fails, named",
          "[metrics][covisibility]") {
  // Two D435 looking ahead and a TiM571 (270 deg) looking back from the rear edge: its edges
  // at +-135 deg from behind diverge from the cameras' +-43.5 deg (87 deg FOV) ahead.
  test::TempFolder folder;
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  const std::string cameras =
      "  - {id: cam_left, sensor: realsense_d435, mode: z16_848x480_30, pose: {xyz: [0.21, 0.05, "
      "0.3], rpy_deg: [0, 15, 0]}}\n"
      "  - {id: cam_right, sensor: realsense_d435, mode: z16_848x480_30, pose: {xyz: [0.21, -0.05, "
      "0.3], rpy_deg: [0, 15, 0]}}\n";
  const std::string rear =
      "  - {id: rear_lidar, sensor: sick_tim571, mode: 0.33deg_15hz, pose: {xyz: [-0.21, 0, 0.2], "
      "rpy_deg: [0, 0, 180]}}\n";
  const std::string front =
      "  - {id: front_lidar, sensor: sick_tim571, mode: 0.33deg_15hz, pose: {xyz: [0.21, 0, 0.2], "
      "rpy_deg: [0, 0, 0]}}\n";
  const auto rig_with = [&](const std::string& name, const std::string& lidar) {
    return io::load_rig(folder.write(name,
                                     "name: calibration case\nbody: {radius: 0.2, height: 0.5}\n"
                                     "distance_of_interest: 3.0\nmounts:\n" +
                                         cameras + lidar));
  };
  model::CalibrationRequirement needed;
  needed.min_overlap = 0.5;
  const model::Rig behind = rig_with("behind.yaml", rear);
  const metrics::RequirementResult fails =
      metrics::calibration_verdict(behind, needed, metrics::covisibility(behind, library, 3.0));
  CHECK(fails.verdict == metrics::Verdict::fail);
  CHECK(fails.limiting_mounts == std::vector<std::string>{"rear_lidar"});
  const model::Rig ahead = rig_with("ahead.yaml", front);
  CHECK(metrics::calibration_verdict(ahead, needed, metrics::covisibility(ahead, library, 3.0))
            .verdict == metrics::Verdict::pass);
}

TEST_CASE("calibration: the requirement is read with its line, bad values named",
          "[metrics][covisibility]") {
  test::TempFolder folder;
  const std::string base = "name: r\nrange: {distance: 3.0}\n";
  const model::Requirements read = io::load_requirements(
      folder.write("ok.yaml", base + "calibration: {pairs: connected, min_overlap_m2: 0.5}\n"));
  REQUIRE(read.calibration);
  CHECK(read.calibration->min_overlap == 0.5);
  CHECK_FALSE(read.calibration->all_pairs);
  CHECK(read.calibration->where.line == 3);
  CHECK_THROWS_AS(io::load_requirements(folder.write(
                      "bad.yaml", base + "calibration: {pairs: some, min_overlap_m2: 0.5}\n")),
                  model::InputError);
  CHECK_THROWS_AS(io::load_requirements(folder.write(
                      "neg.yaml", base + "calibration: {pairs: all, min_overlap_m2: -1}\n")),
                  model::InputError);
}
