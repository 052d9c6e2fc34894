// Issue 32: select verifies each failure of a robust rig with every mount's exact sections
// computed once (metrics::sectors_broken_by); each verdict must equal the one a whole
// compute_coverage of the rig without the failed mounts gives (the path `check` and the
// reports use, verified against the exact sampler).
#include "rigdesign/metrics/failure_coverage.hpp"

#include <catch2/catch.hpp>
#include <string>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

TEST_CASE("failure verdicts from shared sections equal a coverage of the rig without them",
          "[metrics]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path("rigs/ur_cleaner.yaml"));
  std::vector<model::SectorRequirement> sectors =
      io::load_requirements(source_path("rigs/requirements/ur_cleaner.yaml")).sectors;
  metrics::CoverageSettings settings;
  settings.step = 5.0 * 3.14159265358979323846 / 180.0;
  // Each mount alone, all but the first, and none.
  std::vector<std::vector<bool>> failures;
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    failures.emplace_back(rig.mounts.size(), false);
    failures.back()[m] = true;
  }
  failures.emplace_back(rig.mounts.size(), true);
  failures.back()[0] = false;
  failures.emplace_back(rig.mounts.size(), false);
  const std::vector<std::vector<std::size_t>> broken =
      metrics::sectors_broken_by(rig, library, sectors, settings, failures);
  REQUIRE(broken.size() == failures.size());
  int breaking = 0;
  int harmless = 0;
  for (std::size_t f = 0; f < failures.size(); ++f) {
    model::Rig rest = rig;
    rest.mounts.clear();
    for (std::size_t m = 0; m < rig.mounts.size(); ++m)
      if (!failures[f][m]) rest.mounts.push_back(rig.mounts[m]);
    const metrics::RigCoverage whole = metrics::compute_coverage(rest, library, sectors, settings);
    std::vector<std::size_t> expected;
    for (std::size_t s = 0; s < whole.sectors.size(); ++s)
      if (!whole.sectors[s].pass) expected.push_back(s);
    INFO("failure " << f);
    CHECK(broken[f] == expected);
    (expected.empty() ? harmless : breaking) += 1;
  }
  // The comparison decides something both ways: the intact rig meets every sector (paper 1's
  // rig for these requirements) and losing all but the front camera does not.
  CHECK(broken.back().empty());
  CHECK(breaking >= 1);
  CHECK(harmless >= 1);
}
