#include <catch2/catch.hpp>
#include <filesystem>
#include <set>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/rig_references.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/file_kind.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using rigdesign::test::source_path;

namespace {

std::vector<std::string> yaml_files_in(const std::string& folder) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(source_path(folder))) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("every bundled rig and requirement file loads and resolves") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const auto rigs = yaml_files_in("rigs");
  CHECK(rigs.size() >= 3);
  for (const std::string& file : rigs) {
    INFO(file);
    REQUIRE(io::detect_file_kind(file) == io::FileKind::rig);
    const model::Rig rig = io::load_rig(file);
    const model::Diagnostics references = io::check_rig_references(rig, library);
    CHECK(references.items().empty());  // no unknown reference, no distance out of range
  }
  for (const std::string& file : yaml_files_in("rigs/requirements")) {
    INFO(file);
    REQUIRE(io::detect_file_kind(file) == io::FileKind::requirements);
    CHECK_NOTHROW(io::load_requirements(file));
  }
}

TEST_CASE("the sensor library holds the sensors the product card asks for") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  CHECK(library.sensors.size() >= 12);
  for (const char* id :
       {"azure_kinect_dk", "pmd_pico_flexx", "velodyne_vlp16", "kinect_v1", "sick_lms100",
        "realsense_d435", "realsense_d455", "ouster_os1_64", "hokuyo_ust_10lx", "livox_mid360",
        "orbbec_femto_bolt", "zed2", "rplidar_a2m8"}) {
    INFO(id);
    CHECK(library.find(id) != nullptr);
  }
  for (const model::Sensor& sensor : library.sensors) {
    INFO(sensor.id);
    CHECK_FALSE(sensor.source.empty());
    CHECK_FALSE(sensor.price.source.empty());
    CHECK(sensor.price.year >= 2010);
  }
  // Azure Kinect: the four depth modes of its datasheet; VLP-16: 5, 10, 15 and 20 Hz.
  const model::Sensor& azure = *library.find("azure_kinect_dk");
  for (const char* mode :
       {"nfov_unbinned_30", "nfov_binned_30", "wfov_binned_30", "wfov_unbinned_15"}) {
    CHECK(azure.find_mode(mode) != nullptr);
  }
  std::set<double> rates;
  for (const model::SensorMode& mode : library.find("velodyne_vlp16")->modes)
    rates.insert(mode.frequency);
  CHECK(rates == std::set<double>{5, 10, 15, 20});
}

TEST_CASE("pixel grids give angular resolution, per-second data rates give bytes per frame") {
  test::TempFolder folder;
  const std::string file = folder.write("lib.yaml", R"(reference_machine: test
sensors:
  - id: cam
    name: Camera
    technology: tof
    source: test
    price: {usd: 100, year: 2020, basis: estimate, source: test}
    mode_defaults:
      range: {min: 0.1, max: 4}
      noise: {a: 0.01}
      light: {dark: true, indoor: true, sunlight: false}
      driver_cpu: {cores: 0.1, basis: estimate}
    modes:
      - {id: grid, frequency: 10, pixels: [600, 400], bytes_per_point: 2,
         fov: {shape: pyramid, horizontal_deg: 60, vertical_deg: 40}}
      - {id: spinning, frequency: 15, angular_resolution_deg: [0.3, 2.0], points_per_frame: 19290,
         bytes_per_second: 940368,
         fov: {shape: band, elevation_min_deg: -15, elevation_max_deg: 15}}
)");
  const model::SensorLibrary library = io::load_sensor_library(file);
  const model::SensorMode& grid = library.sensors[0].modes[0];
  CHECK(grid.angular_resolution_h == Approx(model::deg_to_rad(0.1)));   // 60 deg / 600 px
  CHECK(*grid.angular_resolution_v == Approx(model::deg_to_rad(0.1)));  // 40 deg / 400 px
  CHECK(grid.points_per_frame == 240000);
  CHECK(grid.bytes_per_frame == 480000);
  const model::SensorMode& spinning = library.sensors[0].modes[1];
  CHECK(spinning.fov.horizontal() == Approx(2 * 3.14159265358979));  // band default: 360 deg
  CHECK(spinning.fov.vertical() == Approx(model::deg_to_rad(30)));
  CHECK(spinning.bytes_per_frame * 15 == Approx(940368));
}
