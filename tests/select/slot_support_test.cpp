// Issue 52 item 3: a catalog slot declares the support it needs (a mast, a bracket) and its
// price. The price counts in every option of that slot, the chosen rig declares the support,
// and its resultant cost C_s includes it. Prices are read from sensors.yaml's text here.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <numbers>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/yaml_writers.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/select/selection.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using test::source_path;

namespace {

// A D435 pitched 30 deg down on a 200 USD mast above a 0.5 m body, or on the front bumper
// without one; either sees the front's floor and space.
std::string mast_catalog() {
  return "name: Mast or bumper\nsensor_library: " + source_path("sensors.yaml") + R"(
body: {radius: 0.3, height: 0.5}
distance_of_interest: 2.0
reference_machine: test
filtering_seconds_per_point: 3.5e-7
sensors:
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
slots:
  - id: mast
    pose: {xyz: [0.1, 0, 0.7], rpy_deg: [0, 30, 0]}
    seat: bottom
    support: {shape: cylinder, radius: 0.02, height: 0.2, pose: {xyz: [0.1, 0, 0.6], rpy_deg: [0, 0, 0]}, price_usd: 200}
    allows: [realsense_d435]
  - id: bumper
    pose: {xyz: [0.34, 0, 0.3], rpy_deg: [0, 30, 0]}
    allows: [realsense_d435]
transfer:
  - {id: onboard, capacity_bps: 3.0e9, price_usd: 0}
cpus:
  - {id: small, cores: 3.0, price_usd: 300}
  - {id: big, cores: 8.0, price_usd: 800}
)";
}

double usd_in_sensors_yaml(const std::string& id) {
  for (const YAML::Node& sensor : YAML::LoadFile(source_path("sensors.yaml"))["sensors"]) {
    if (sensor["id"].as<std::string>() == id) return sensor["price"]["usd"].as<double>();
  }
  FAIL("no " << id);
  return 0.0;
}

}  // namespace

TEST_CASE("select: a slot's support is bought with its sensor", "[select]") {
  test::TempFolder folder;
  const model::Catalog catalog = io::load_catalog(folder.write("c.yaml", mast_catalog()));
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  REQUIRE(catalog.slots.size() == 2);
  REQUIRE(catalog.slots[0].support.has_value());
  CHECK(catalog.slots[0].support->id == "mast_support");
  CHECK(catalog.slots[0].support->price == 200);
  CHECK_FALSE(catalog.slots[1].support.has_value());
  metrics::CoverageSettings settings;
  settings.step = 10.0 * std::numbers::pi / 180.0;
  settings.raster_cell = 0.02;
  const select::SelectionSpace space(catalog, library, settings);
  select::SatisficingTargets targets;
  targets.sectors = {{"front", -0.2, 0.2, 0.05, 0.05, {}}};
  std::vector<std::vector<const select::CatalogOption*>> kept;
  const select::SearchProblem problem = space.problem_for(targets, kept);
  const double d435 = usd_in_sensors_yaml("realsense_d435");
  REQUIRE(problem.slots[0].size() == 1);
  REQUIRE(problem.slots[1].size() == 1);
  CHECK(problem.slots[0][0].price == d435 + 200);
  CHECK(problem.slots[1][0].price == d435);
  // Either alone meets the front: the bumper is 200 USD cheaper.
  const select::SearchResult bounded = select::branch_and_bound(problem);
  const select::SearchResult exhaustive = select::brute_force(problem);
  REQUIRE(bounded.found);
  CHECK(bounded.choice == std::vector<int>{-1, 0});
  CHECK(bounded.cost.total == exhaustive.cost.total);

  // The mast's rig carries its support, priced in C_s, and writes it back.
  const model::Rig rig = space.rig_for({kept[0][0]});
  REQUIRE(rig.supports.size() == 1);
  CHECK(metrics::compute_resultant(rig, library).sensor_cost == d435 + 200);
  const std::string text = io::rig_to_yaml(rig, source_path("sensors.yaml"), "", "", folder.path());
  INFO(text);
  const std::size_t supports = text.find("\nsupports:\n  - {id: ");
  REQUIRE(supports != std::string::npos);
  const std::string line = text.substr(supports + 1, text.find('\n', supports + 12) - supports);
  CHECK(line.find("mast_support") != std::string::npos);
  CHECK(line.find("shape: cylinder, radius: 0.02, height: 0.2, pose: {xyz: [0.1, 0, 0.6], "
                  "rpy_deg: [0, 0, 0]}, price_usd: 200}") != std::string::npos);
}
