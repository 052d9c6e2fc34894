#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "rigdesign/io/config/pipeline_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

std::string real_cloud(const std::string& name) {
  return std::string(RIGDESIGN_SOURCE_DIR) + "/../shared/data/real/" + name;
}

const std::string kTinyCloud = R"(VERSION 0.7
FIELDS x y z
SIZE 4 4 4
TYPE F F F
COUNT 1 1 1
WIDTH 4
HEIGHT 1
POINTS 4
DATA ascii
0 0 0
0.01 0 0
0 0.01 0
0.5 0.5 0.5
)";

}  // namespace

TEST_CASE("the real clouds filter without error, in the optical frame and in the robot frame") {
  if (!std::filesystem::exists(real_cloud("office1.pcd"))) {
    WARN("shared/data/real is absent: skipped");
    return;
  }
  const CliResult plain =
      run_cli({"filter", "--cloud", real_cloud("office1.pcd"), real_cloud("five_people.pcd"),
               "--pipeline", "P3", "--repeat", "1", "--json"});
  INFO(plain.err);
  REQUIRE(plain.exit_code == 0);
  const auto report = nlohmann::json::parse(plain.out);
  REQUIRE(report["clouds"].size() == 2);
  CHECK(report["clouds"][0]["points"] == 254456);  // SOURCES.md's finite-point count
  CHECK(report["clouds"][0]["stages"].size() == 3);
  // Two threads for SOR (issue 17) keep every stage's output: the same point counts.
  const CliResult threaded = run_cli({"filter", "--cloud", real_cloud("office1.pcd"), "--pipeline",
                                      "P3", "--repeat", "1", "--threads", "2", "--json"});
  REQUIRE(threaded.exit_code == 0);
  const auto threaded_report = nlohmann::json::parse(threaded.out);
  for (std::size_t s = 0; s < 3; ++s) {
    CHECK(threaded_report["clouds"][0]["stages"][s]["points_out"] ==
          report["clouds"][0]["stages"][s]["points_out"]);
  }
  // Mounted as the UR Cleaner's front camera, the same cloud gets a filtering load.
  const CliResult mounted =
      run_cli({"filter", "--cloud", real_cloud("table_scene_mug_stereo_textured.pcd"), "--rig",
               source_path("rigs/ur_cleaner.yaml"), "--mount", "front_camera", "--pipeline", "P4",
               "--repeat", "1", "--json"});
  REQUIRE(mounted.exit_code == 0);
  const auto item = nlohmann::json::parse(mounted.out)["clouds"][0];
  CHECK(item["filtering_load_cores"].get<double>() > 0.0);
}

TEST_CASE("a pipeline file is pure data, an unknown stage is a located error") {
  TempFolder folder;
  const std::string good =
      folder.write("good.yaml",
                   "name: mine\nstages:\n  - voxel_grid: {leaf: 0.05}\n"
                   "  - statistical_outlier\n  - floor_removal_2: {ransac: {max_tilt_deg: 10}}\n");
  const model::Pipeline pipeline = io::load_pipeline(good);
  REQUIRE(pipeline.stages.size() == 3);
  CHECK(std::get<model::VoxelGridParams>(pipeline.stages[0]).leaf == 0.05);
  CHECK(std::get<model::StatisticalOutlierParams>(pipeline.stages[1]).neighbours ==
        10);  // paper default
  const std::string bad = folder.write(
      "bad.yaml", "name: mine\nstages:\n  - voxel_grid: {leaf: 0.05}\n  - smooth: {}\n");
  const std::string cloud = folder.write("tiny.pcd", kTinyCloud);
  const CliResult result = run_cli({"filter", "--cloud", cloud, "--pipeline", bad});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("bad.yaml:4:5: stages[1]: unknown stage 'smooth'") != std::string::npos);
}

TEST_CASE("filter: bad input is exit 2") {
  TempFolder folder;
  const std::string cloud = folder.write("tiny.pcd", kTinyCloud);
  SECTION("a voxel size of zero") {
    const std::string pipeline =
        folder.write("p.yaml", "name: p\nstages:\n  - voxel_grid: {leaf: 0}\n");
    const CliResult result = run_cli({"filter", "--cloud", cloud, "--pipeline", pipeline});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("p.yaml:3:") != std::string::npos);
    CHECK(result.err.find("leaf: must be > 0") != std::string::npos);
  }
  SECTION("an empty cloud") {
    std::string empty = kTinyCloud;
    empty = empty.substr(0, empty.find("WIDTH")) + "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n";
    const CliResult result = run_cli({"filter", "--cloud", folder.write("empty.pcd", empty)});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("has no finite point") != std::string::npos);
  }
  SECTION("a truncated binary cloud") {
    std::string binary = kTinyCloud;
    binary.replace(binary.find("DATA ascii"), 10, "DATA binary");
    binary = binary.substr(0, binary.find("DATA binary") + 12) +
             std::string(20, '\0');  // 4 x 12 bytes declared
    const CliResult result = run_cli({"filter", "--cloud", folder.write("cut.pcd", binary)});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("cut.pcd") != std::string::npos);
  }
  SECTION("an unknown preset") {
    CHECK(run_cli({"filter", "--cloud", cloud, "--pipeline", "P9"}).exit_code == 2);
  }
}
