// Paper 1, Table 1: the UR Cleaner rig has F = 15 Hz, R = 122 mm, N = 30 mm, L = true.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/rig_references.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;
using rigdesign::test::source_path;

TEST_CASE("UR Cleaner reproduces paper 1's Table 1") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path("rigs/ur_cleaner.yaml"));
  REQUIRE_FALSE(io::check_rig_references(rig, library).has_errors());
  const metrics::ResultantMetrics metrics = metrics::compute_resultant(rig, library);

  CHECK(metrics.frequency.value == 15.0);
  // Table 1: R = 122 mm (+-1 mm), from the VLP-16's 2 deg vertical step at 3.5 m.
  CHECK(std::abs(metrics.point_spacing.value - 0.122) <= 0.001);
  CHECK(metrics.point_spacing.mounts == std::vector<std::string>{"top_lidar"});
  CHECK(metrics.noise.value == Approx(0.030).margin(1e-9));
  CHECK(metrics.noise.mounts == std::vector<std::string>{"top_lidar"});

  // L = true for the conditions the UR Cleaner requires.
  const model::Requirements requirements =
      io::load_requirements(source_path("rigs/requirements/ur_cleaner.yaml"));
  REQUIRE_FALSE(requirements.lighting.empty());
  for (model::LightCondition condition : requirements.lighting) {
    CHECK(metrics.light_for(condition).immune);
  }
}
