#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

using namespace rigdesign::test;

TEST_CASE("metrics --json on the UR Cleaner gives Table 1's values") {
  const CliResult result = run_cli({"metrics", source_path("rigs/ur_cleaner.yaml"), "--json"});
  REQUIRE(result.exit_code == 0);
  const auto report = nlohmann::json::parse(result.out);
  const auto& resultant = report["resultant"];
  CHECK(resultant["F"]["value"].get<double>() == 15.0);
  CHECK(std::abs(resultant["R"]["value"].get<double>() - 0.122) <= 0.001);
  CHECK(resultant["N"]["value"].get<double>() == Approx(0.030));
  CHECK(resultant["R"]["limiting_mounts"] == nlohmann::json::array({"top_lidar"}));
  // Sensor cost: one Azure Kinect ($399), three pico flexx ($480 each, estimate), one VLP-16
  // ($4000).
  CHECK(resultant["sensor_cost_usd"].get<double>() == Approx(399 + 3 * 480 + 4000));
  CHECK(report["mounts"].size() == 5);
  for (const auto& requirement : report["requirements"]["results"]) {
    CHECK(requirement["verdict"] != "fail");
  }
}

TEST_CASE("metrics prints the resultant metrics with the sensors that set them") {
  const CliResult result = run_cli({"metrics", source_path("rigs/ur_cleaner.yaml")});
  REQUIRE(result.exit_code == 0);
  CHECK(result.out.find("F = 15 Hz") != std::string::npos);
  CHECK(result.out.find("R = 122.2 mm") != std::string::npos);
  CHECK(result.out.find("N = 30.0 mm") != std::string::npos);
  CHECK(result.out.find("L = true") != std::string::npos);
}
