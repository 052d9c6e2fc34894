// Issue 15: on a real catalog with pose ranges (sensors rasterised from sensors.yaml), the
// branch and bound on compressed classes finds what the brute force finds on the raw
// rasters, with and without robustness to a single failure.
#include <catch2/catch.hpp>
#include <numbers>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/select/selection.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// Four slots: a front camera at four pitches, two side cameras at three pitches, turned 45
// or 90 deg, and a high front camera at two pitches; 4 x 2 + 6 x 2 + 6 x 2 + 2 = 34
// options, 9 x 13 x 13 x 3 = 4563 assignments.
std::string pose_range_catalog() {
  return "name: Ranges\nsensor_library: " + source_path("sensors.yaml") + R"(
body: {radius: 0.45, height: 1.0}
distance_of_interest: 2.0
reference_machine: test
filtering_seconds_per_point: 3.5e-7
sensors:
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
  - {sensor: pmd_pico_flexx, modes: [mode_9_15fps]}
slots:
  - id: front
    pose: {xyz: [0.46, 0, 0.6], rpy_deg: [0, {min: 0, max: 45, step: 15}, 0]}
    recessed: true
    allows: [realsense_d435, pmd_pico_flexx]
  - id: left
    pose: {xyz: [0, 0.46, 0.3], rpy_deg: [0, {min: 0, max: 40, step: 20}, {min: 45, max: 90, step: 45}]}
    recessed: true
    allows: [realsense_d435, pmd_pico_flexx]
  - id: right
    pose: {xyz: [0, -0.46, 0.3], rpy_deg: [0, {min: 0, max: 40, step: 20}, {min: -90, max: -45, step: 45}]}
    recessed: true
    allows: [realsense_d435, pmd_pico_flexx]
  - id: front_high
    pose: {xyz: [0.46, 0, 0.9], rpy_deg: [0, {min: 20, max: 40, step: 20}, 0]}
    recessed: true
    allows: [realsense_d435]
transfer:
  - {id: onboard, capacity_bps: 3.0e9, price_usd: 0}
cpus:
  - {id: small, cores: 3.0, price_usd: 300}
  - {id: big, cores: 8.0, price_usd: 800}
)";
}

model::SectorRequirement sector(const char* name, double from_deg, double to_deg, double complete,
                                double floor) {
  constexpr double kRad = std::numbers::pi / 180.0;
  return {name, from_deg * kRad, to_deg * kRad, complete, floor, {}};
}

}  // namespace

TEST_CASE("pose ranges: branch and bound equals brute force on a rasterised catalog", "[select]") {
  TempFolder folder;
  const model::Catalog catalog = io::load_catalog(folder.write("c.yaml", pose_range_catalog()));
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  // select's bound on its work counts the options before rasterising them: the same 34.
  REQUIRE(select::count_catalog_options(catalog) == 34);
  metrics::CoverageSettings settings;
  settings.step = 10.0 * std::numbers::pi / 180.0;  // 36 angles
  settings.raster_cell = 0.02;
  const select::SelectionSpace space(catalog, library, settings);
  REQUIRE(space.option_count() == 34);

  int found = 0;
  int robust_found = 0;
  for (const double scale : {0.4, 0.7, 1.0, 1.3}) {
    INFO("threshold scale " << scale);
    select::SatisficingTargets targets;
    targets.sectors = {sector("front", -20, 20, 0.3 * scale, 0.5 * scale),
                       sector("left", 70, 110, 0.15 * scale, 0.3 * scale),
                       sector("right", -110, -70, 0.15 * scale, 0.3 * scale)};
    std::vector<std::vector<const select::CatalogOption*>> kept;
    select::SearchProblem problem = space.problem_for(targets, kept);
    const select::SearchResult exhaustive = select::brute_force(problem);
    const select::SearchResult bounded = select::branch_and_bound(problem);
    REQUIRE(bounded.found == exhaustive.found);
    if (exhaustive.found) {
      ++found;
      CHECK(bounded.cost.total == exhaustive.cost.total);
      CHECK(bounded.margin == exhaustive.margin);
      CHECK(bounded.margins == exhaustive.margins);
      CHECK(bounded.nodes < exhaustive.nodes);
    }
    // Any one sensor may fail: the front must keep half its thresholds (two front cameras
    // can stand in for each other), the sides may go blind.
    problem.robustness.single_failure = true;
    problem.robustness.sectors = problem.sectors;
    problem.robustness.sectors[0].min_complete *= 0.5;
    problem.robustness.sectors[0].min_floor *= 0.5;
    for (std::size_t s = 1; s < problem.sectors.size(); ++s) {
      problem.robustness.sectors[s].min_complete = 0.0;
      problem.robustness.sectors[s].min_floor = 0.0;
    }
    const select::SearchResult robust_exhaustive = select::brute_force(problem);
    const select::SearchResult robust_bounded = select::branch_and_bound(problem);
    REQUIRE(robust_bounded.found == robust_exhaustive.found);
    if (robust_exhaustive.found) {
      ++robust_found;
      CHECK(robust_bounded.cost.total == robust_exhaustive.cost.total);
      CHECK(robust_bounded.margin == robust_exhaustive.margin);
      if (exhaustive.found) CHECK(robust_bounded.cost.total >= bounded.cost.total);
    }
  }
  CHECK(found >= 2);
  CHECK(robust_found >= 1);
}
