// Measured filtering loads: the file round-trips, catalogs take the measured value for a
// sensor unless the candidate gives its own, and metrics turns s/point into U_f with the
// datasheet's points per second (paper 1, eq. 5).
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/filtering_loads_io.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

const std::string kLoads = R"(machine: "test machine"
pipeline: "P2"
sensors:
  - {sensor: azure_kinect_dk, seconds_per_point: 1.0e-8}
  - {sensor: pmd_pico_flexx, seconds_per_point: 2.0e-8}
)";

}  // namespace

TEST_CASE("a filtering-loads file round-trips and merges sensor by sensor", "[filtering_loads]") {
  const TempFolder folder;
  model::FilteringLoads loads{
      "m",
      "P4",
      "office",
      20,
      {{"azure_kinect_dk", "nfov_unbinned_30", 3.94e-8, 260468, 0.0102, {}}},
      {}};
  const std::string path = folder.write("loads.yaml", io::filtering_loads_to_yaml(loads, "a\nb"));
  const model::FilteringLoads back = io::load_filtering_loads(path);
  CHECK(back.machine == "m");
  CHECK(back.pipeline == "P4");
  CHECK(back.frames == 20);
  REQUIRE(back.sensors.size() == 1);
  CHECK(back.sensors[0].seconds_per_point == Approx(3.94e-8).epsilon(1e-6));
  CHECK(back.sensors[0].points_per_frame == 260468);

  const model::FilteringLoads newer{
      "m2", "P2", "corridor", 5, {{"velodyne_vlp16", "", 1e-7, 1, 1, {}}}, {}};
  const model::FilteringLoads merged = io::merge_filtering_loads(back, newer);
  CHECK(merged.machine == "m2");
  REQUIRE(merged.sensors.size() == 2);
  CHECK(merged.find("azure_kinect_dk") != nullptr);
  CHECK(merged.find("velodyne_vlp16")->seconds_per_point == 1e-7);
}

TEST_CASE("a catalog takes measured loads unless a candidate gives its own", "[filtering_loads]") {
  const TempFolder folder;
  std::string catalog = file_text(source_path("rigs/catalogs/ur_cleaner.yaml"));
  catalog.replace(catalog.find("sensor_library: "), 0, "filtering_loads: loads.yaml\n");
  const std::string own = "{sensor: pmd_pico_flexx, modes: [";
  REQUIRE(catalog.find(own) != std::string::npos);
  catalog.replace(catalog.find(own), own.size(),
                  "{sensor: pmd_pico_flexx, filtering_seconds_per_point: 5.0e-7, modes: [");
  // The catalog names its sensor library and URDF relative to itself.
  const std::string library = "sensor_library: ";
  const std::size_t at = catalog.find(library) + library.size();
  catalog.replace(at, catalog.find('\n', at) - at, "\"" + source_path("sensors.yaml") + "\"");
  folder.write("loads.yaml", kLoads);
  const model::Catalog loaded = io::load_catalog(folder.write("catalog.yaml", catalog));
  for (const model::CandidateSensor& candidate : loaded.sensors) {
    if (candidate.sensor_id == "azure_kinect_dk")
      CHECK(candidate.filtering_seconds_per_point == 1.0e-8);
    if (candidate.sensor_id == "pmd_pico_flexx")
      CHECK(candidate.filtering_seconds_per_point == 5.0e-7);
    if (candidate.sensor_id == "velodyne_vlp16") CHECK_FALSE(candidate.filtering_seconds_per_point);
  }

  catalog.replace(catalog.find("filtering_loads: loads.yaml"), 27, "filtering_loads: missing.yaml");
  const std::string broken = folder.write("broken.yaml", catalog);
  try {
    io::load_catalog(broken);
    FAIL("expected an error");
  } catch (const model::InputError& error) {
    const model::Diagnostic& first = error.diagnostics().front();
    CHECK(first.field == "filtering_loads");
    CHECK(first.where.line == line_of(catalog, "filtering_loads:"));
    CHECK(first.problem.find("missing.yaml") != std::string::npos);
  }
}

TEST_CASE("metrics --filtering-loads: U_f = s/point x the datasheet's points per second",
          "[filtering_loads]") {
  const TempFolder folder;
  const std::string loads = folder.write("loads.yaml", kLoads);
  const CliResult result = run_cli(
      {"metrics", source_path("rigs/ur_cleaner.yaml"), "--filtering-loads", loads, "--json"});
  REQUIRE(result.exit_code == 0);
  const nlohmann::json report = nlohmann::json::parse(result.out);
  const nlohmann::json& mounts = report["filtering_load"]["mounts_cores"];
  // Azure Kinect NFOV unbinned: 640 x 576 pixels at 30 Hz; pico flexx 224 x 171 at 15 Hz.
  CHECK(mounts["front_camera"].get<double>() == Approx(1e-8 * 640 * 576 * 30));
  CHECK(mounts["left_camera"].get<double>() == Approx(2e-8 * 224 * 171 * 15));
  CHECK(mounts["top_lidar"].is_null());
  CHECK(report["filtering_load"]["total_cores"].get<double>() ==
        Approx(1e-8 * 640 * 576 * 30 + 3 * 2e-8 * 224 * 171 * 15));
}

TEST_CASE("filter --write-loads records every sensor of the rig, without --scene it is refused",
          "[filtering_loads]") {
  const TempFolder folder;
  const std::string path = folder.path() + "/loads.yaml";
  const CliResult result =
      run_cli({"filter", "--rig", source_path("rigs/ur_cleaner.yaml"), "--scene", "corridor",
               "--frames", "2", "--pipeline", "P3", "--write-loads", path, "--json"});
  REQUIRE(result.exit_code == 0);
  const nlohmann::json report = nlohmann::json::parse(result.out);
  const model::FilteringLoads loads = io::load_filtering_loads(path);
  CHECK(loads.pipeline == "P3");
  CHECK(loads.scene == "corridor");
  CHECK(loads.sensors.size() == 3);  // the Azure Kinect, the pico flexx (three mounts), the VLP-16
  for (const nlohmann::json& mount : report["mounts"]) {
    if (mount["mount"] != "front_camera") continue;
    const double per_point =
        mount["median_s"].get<double>() / mount["points_per_frame"].get<double>();
    CHECK(loads.find("azure_kinect_dk")->seconds_per_point == Approx(per_point).epsilon(1e-4));
  }
  const CliResult refused = run_cli({"filter", "--cloud", "x.pcd", "--write-loads", path});
  CHECK(refused.exit_code == 2);
  CHECK(refused.err.find("--write-loads") != std::string::npos);
}
