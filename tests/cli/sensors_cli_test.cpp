// `rigdesign sensors`: the bundled library holds the sensors of today's ROS robots, and the
// list, search and full print agree with the file's own text, read here with yaml-cpp.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <set>

#include "support/cli_runner.hpp"

using namespace rigdesign::test;

namespace {

YAML::Node bundled_library() {
  return YAML::LoadFile(source_path("sensors.yaml"));
}

// A mode field, from the mode or else the sensor's mode_defaults (the schema's inheritance).
YAML::Node mode_field(const YAML::Node& sensor, const YAML::Node& mode, const std::string& key) {
  if (mode[key]) return mode[key];
  return sensor["mode_defaults"][key];
}

std::set<std::string> ids_in(const nlohmann::json& list) {
  std::set<std::string> ids;
  for (const auto& sensor : list["sensors"]) ids.insert(sensor["id"].get<std::string>());
  return ids;
}

}  // namespace

TEST_CASE("the bundled library holds at least 35 sensors, the ones ROS robots carry among them") {
  const CliResult result = run_cli({"sensors", "--format", "json"});
  REQUIRE(result.exit_code == 0);
  const std::set<std::string> ids = ids_in(nlohmann::json::parse(result.out));
  CHECK(ids.size() == bundled_library()["sensors"].size());
  CHECK(ids.size() >= 35);
  // Issue 18's list, in the library's ids.
  for (const char* id :
       {"oakd_pro",       "oakd_lite",   "oakd_s2",          "realsense_d405",   "realsense_d415",
        "realsense_l515", "zed_x",       "orbbec_gemini2",   "orbbec_gemini335", "rplidar_a1m8",
        "rplidar_s2",     "rplidar_s3",  "robotis_lds01",    "robotis_lds02",    "hokuyo_uam01",
        "hokuyo_utm30lx", "sick_tim571", "sick_microscan3",  "sick_nanoscan3",   "ouster_os0",
        "ouster_os2",     "hesai_xt32",  "hesai_pandarqt64", "velodyne_vlp32c",  "livox_avia",
        "livox_hap",      "unitree_l1"}) {
    INFO(id);
    CHECK(ids.count(id) == 1);
  }
}

TEST_CASE("every bundled sensor names its source and says how its price is known") {
  for (const YAML::Node& sensor : bundled_library()["sensors"]) {
    INFO(sensor["id"].as<std::string>());
    CHECK(sensor["source"].as<std::string>().size() >= 20);
    const std::string basis = sensor["price"]["basis"].as<std::string>();
    CHECK((basis == "datasheet" || basis == "estimate" || basis == "measured"));
    CHECK(!sensor["price"]["source"].as<std::string>().empty());
  }
}

TEST_CASE("sensors --technology --min-range keeps exactly the sensors the file says qualify") {
  // Expected set from the file's text: a 2D scanner with some mode reaching 20 m.
  std::set<std::string> expected;
  for (const YAML::Node& sensor : bundled_library()["sensors"]) {
    if (sensor["technology"].as<std::string>() != "lidar_2d") continue;
    for (const YAML::Node& mode : sensor["modes"]) {
      if (mode_field(sensor, mode, "range")["max"].as<double>() >= 20.0) {
        expected.insert(sensor["id"].as<std::string>());
      }
    }
  }
  REQUIRE(expected.size() >= 4);
  const CliResult result =
      run_cli({"sensors", "--technology", "lidar_2d", "--min-range", "20", "--format", "json"});
  REQUIRE(result.exit_code == 0);
  CHECK(ids_in(nlohmann::json::parse(result.out)) == expected);
}

TEST_CASE("sensors --max-price --min-rate --sort price lists cheap fast sensors cheapest first") {
  const CliResult result = run_cli(
      {"sensors", "--max-price", "400", "--min-rate", "60", "--sort", "price", "--format", "json"});
  REQUIRE(result.exit_code == 0);
  const auto list = nlohmann::json::parse(result.out)["sensors"];
  std::set<std::string> expected;
  for (const YAML::Node& sensor : bundled_library()["sensors"]) {
    if (sensor["price"]["usd"].as<double>() > 400) continue;
    for (const YAML::Node& mode : sensor["modes"]) {
      if (mode_field(sensor, mode, "frequency").as<double>() >= 60) {
        expected.insert(sensor["id"].as<std::string>());
      }
    }
  }
  CHECK(ids_in(nlohmann::json{{"sensors", list}}) == expected);
  for (std::size_t i = 1; i < list.size(); ++i) {
    CHECK(list[i - 1]["price"]["usd"].get<double>() <= list[i]["price"]["usd"].get<double>());
  }
}

TEST_CASE("sensors ID prints one sensor with the rates the datasheet implies") {
  const CliResult result = run_cli({"sensors", "rplidar_s2", "--format", "json"});
  REQUIRE(result.exit_code == 0);
  const auto sensor = nlohmann::json::parse(result.out);
  CHECK(sensor["technology"] == "lidar_2d");
  REQUIRE(sensor["modes"].size() == 2);
  const auto& dense = sensor["modes"][0];
  // DenseBoost: 32,000 samples/s (3200 per 10 Hz turn); an 84-byte capsule per 40 samples.
  CHECK(dense["points_per_second"].get<double>() == Approx(32000));
  CHECK(dense["bytes_per_second"].get<double>() == Approx(32000 * 84.0 / 40.0));
  CHECK(dense["range"]["max"].get<double>() == 30.0);
  // Standard mode: 5-byte nodes, 16 m.
  const auto& standard = sensor["modes"][1];
  CHECK(standard["bytes_per_second"].get<double>() == Approx(1600 * 10 * 5));
  CHECK(standard["range"]["max"].get<double>() == 16.0);

  const CliResult text = run_cli({"sensors", "rplidar_s2"});
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("Slamtec RPLIDAR S2") != std::string::npos);
  CHECK(text.out.find("denseboost_10hz") != std::string::npos);
}

TEST_CASE("sensors refuses an unknown id or technology with exit 2 and a suggestion") {
  const CliResult unknown = run_cli({"sensors", "rplidar_s4"});
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err.find("did you mean 'rplidar_s2'") != std::string::npos);
  const CliResult technology = run_cli({"sensors", "--technology", "lidar"});
  CHECK(technology.exit_code == 2);
  CHECK(technology.err.find("lidar_3d_spinning") != std::string::npos);
}

// Reliability reproducers 11 and 12 (issue 31): CLI11's range checks let NaN through, and
// `report --step nan` cut the coverage at one angle. Every such option now refuses NaN.
TEST_CASE("numeric filters and steps refuse NaN with exit 2") {
  for (const char* option : {"--min-range", "--max-price", "--min-rate", "--min-fov-deg"}) {
    INFO(option);
    const CliResult result = run_cli({"sensors", option, "nan"});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find(option) != std::string::npos);
  }
  const CliResult step =
      run_cli({"report", source_path("rigs/cart_two_scanners.yaml"), "--step", "nan"});
  CHECK(step.exit_code == 2);
  CHECK(step.err.find("--step") != std::string::npos);
}
