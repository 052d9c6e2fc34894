// Issue 30: the N-1 table showed losing the Jackal's front laser *raising* the floor mean
// (44.8 -> 44.9 %): its rows are on the raster path, the baseline was the exact one. A union
// only shrinks when a member leaves, so on one path no row may exceed the whole rig's.
#include <catch2/catch.hpp>
#include <string>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

TEST_CASE("N-1: losing a sensor never raises coverage against the same path's baseline",
          "[metrics]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  for (const char* name : {"rigs/jackal.yaml", "rigs/ur_cleaner.yaml", "rigs/turtlebot4.yaml"}) {
    INFO(name);
    const model::Rig rig = io::load_rig(source_path(name));
    metrics::CoverageSettings settings;
    settings.step = 5.0 * 3.14159265358979323846 / 180.0;
    const metrics::RigCoverage coverage = metrics::compute_coverage(rig, library, {}, settings);
    REQUIRE(coverage.without_each.size() == rig.mounts.size());
    for (const metrics::MountLoss& loss : coverage.without_each) {
      INFO(loss.mount_id);
      CHECK(loss.complete.mean <= coverage.complete_raster.mean + 1e-12);
      CHECK(loss.floor.mean <= coverage.floor_raster.mean + 1e-12);
      CHECK(loss.complete.min <= coverage.complete_raster.min + 1e-12);
      CHECK(loss.floor.min <= coverage.floor_raster.min + 1e-12);
    }
  }
}
