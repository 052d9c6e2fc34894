// Issue 38 item 1: the worst case `tolerance_coverage` reports for a bundled rig, checked by
// brute force. Independent of its corner-and-face-centre samples and of its shared sections,
// every mount of paper 1's UR Cleaner is moved at once to a random point of its +-5 mm,
// +-1 deg box (a fixed seed) and a whole compute_coverage of the moved rig gives each sector's
// minima; the reported worst must be realised by its own errors and no random point may fall
// below it by more than the bound docs/tolerance.md states.
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;

namespace {

// The rig with every mount moved by its error in `errors` (by mount id).
model::Rig moved_rig(const model::Rig& rig, const std::vector<metrics::MountError>& errors) {
  model::Rig moved = rig;
  for (const metrics::MountError& error : errors) {
    for (model::Mount& mount : moved.mounts)
      if (mount.id == error.mount_id)
        mount.T_robot_sensor = metrics::with_error(mount.T_robot_sensor, error.error);
  }
  return moved;
}

}  // namespace

TEST_CASE("tolerance: the reported worst case against brute-force sampling of the boxes",
          "[metrics][tolerance]") {
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  model::Rig rig = io::load_rig(test::source_path("rigs/ur_cleaner.yaml"));
  const std::vector<model::SectorRequirement> sectors =
      io::load_requirements(test::source_path("rigs/requirements/ur_cleaner.yaml")).sectors;
  model::PoseTolerance tolerance;
  tolerance.xyz = model::Vec3::Constant(0.005);
  tolerance.rpy = model::Vec3::Constant(model::deg_to_rad(1.0));
  rig.tolerance = tolerance;
  metrics::CoverageSettings settings;
  settings.step = model::deg_to_rad(5.0);
  const std::vector<metrics::SectorTolerance> reported =
      metrics::tolerance_coverage(rig, library, sectors, settings);
  REQUIRE(reported.size() == sectors.size());

  // Each reported worst is what the rig moved by its errors gives.
  for (const metrics::SectorTolerance& sector : reported) {
    INFO(sector.sector.name);
    for (const bool floor : {false, true}) {
      const metrics::WorstShare& worst = floor ? sector.floor : sector.complete;
      const metrics::RigCoverage moved =
          metrics::compute_coverage(moved_rig(rig, worst.errors), library, sectors, settings);
      const auto& found = *std::find_if(
          moved.sectors.begin(), moved.sectors.end(),
          [&](const metrics::SectorCoverage& s) { return s.sector.name == sector.sector.name; });
      CHECK(
          worst.share ==
          Approx(metrics::judged_share(floor ? found.floor.min : found.complete.min)).margin(1e-9));
    }
  }

  // Random joint errors: none below the reported worst by more than the stated bound.
  constexpr double kBound = 0.002;  // docs/tolerance.md: measured gap 0.0 on this rig
  std::mt19937 random(38);          // fixed before any run
  double largest_gap = 0.0;
  int lowered = 0;
  for (int sample = 0; sample < 24; ++sample) {
    std::vector<metrics::MountError> errors;
    for (const model::Mount& mount : rig.mounts) {
      metrics::PoseError error;
      for (int i = 0; i < 3; ++i) {
        error.xyz[i] = std::uniform_real_distribution<double>(-1, 1)(random) * tolerance.xyz[i];
        error.rpy[i] = std::uniform_real_distribution<double>(-1, 1)(random) * tolerance.rpy[i];
      }
      errors.push_back({mount.id, error});
    }
    const metrics::RigCoverage moved =
        metrics::compute_coverage(moved_rig(rig, errors), library, sectors, settings);
    for (std::size_t s = 0; s < sectors.size(); ++s) {
      const double complete = metrics::judged_share(moved.sectors[s].complete.min);
      const double floor = metrics::judged_share(moved.sectors[s].floor.min);
      largest_gap = std::max(
          {largest_gap, reported[s].complete.share - complete, reported[s].floor.share - floor});
      lowered += complete < reported[s].nominal_complete || floor < reported[s].nominal_floor;
    }
  }
  WARN("largest gap below the reported worst: " << largest_gap);
  CHECK(largest_gap <= kBound);
  // The sampling decides something: some random errors do lower a sector below nominal.
  CHECK(lowered > 0);
}
