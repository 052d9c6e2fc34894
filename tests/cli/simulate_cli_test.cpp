#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "rigdesign/io/cloud/cloud_io.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

TEST_CASE("simulate writes one cloud per sensor and frame that reads back, the same for a seed") {
  TempFolder folder;
  const auto run = [&](const std::string& out) {
    return run_cli({"simulate", source_path("rigs/elektron.yaml"), "--scene", "corridor",
                    "--frames", "2", "--seed", "3", "--out", folder.path() + "/" + out});
  };
  REQUIRE(run("a").exit_code == 0);
  REQUIRE(run("b").exit_code == 0);
  for (const char* mount : {"kinect", "front_scanner"}) {
    for (const char* frame : {"frame_0.pcd", "frame_1.pcd"}) {
      const std::string a = folder.path() + "/a/" + mount + "/" + frame;
      const model::PointCloud cloud = io::read_cloud(a);
      CHECK_FALSE(cloud.empty());
      CHECK(cloud.points == io::read_cloud(folder.path() + "/b/" + mount + "/" + frame).points);
    }
  }
  // The 2D scanner's fan is 20 cm above the floor in the robot frame: all its points too.
  for (const model::Point3f& p :
       io::read_cloud(folder.path() + "/a/front_scanner/frame_0.pcd").points) {
    CHECK(std::abs(p.z() - 0.2f) < 0.2f);
  }
}

TEST_CASE("filter measures each sensor's filtering load in a simulated scene") {
  const CliResult result = run_cli({"filter", "--rig", source_path("rigs/elektron.yaml"), "--scene",
                                    "office", "--frames", "2", "--pipeline", "P3", "--json"});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  const auto report = nlohmann::json::parse(result.out);
  REQUIRE(report["mounts"].size() == 2);
  CHECK(report["total_filtering_load_cores"].get<double>() > 0.0);
}

TEST_CASE("simulate takes a scene file: the lab's walls where the room's mesh puts them") {
  TempFolder folder;
  const CliResult result =
      run_cli({"simulate", source_path("rigs/elektron.yaml"), "--scene",
               source_path("rigs/scenes/lab/lab.yaml"), "--frames", "1", "--out", folder.path()});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  // The robot starts at (-1.2, -1.0) facing +x in a 6 x 4 m room (walls at x = +-3, y = +-2);
  // the scanner is 0.27 m ahead of it at 0.2 m. Robot frame: the wall ahead at x = 3 + 1.2,
  // the wall on the left at y = 2 + 1.0, seen from the scanner's x.
  const model::PointCloud scan = io::read_cloud(folder.path() + "/front_scanner/frame_0.pcd");
  const auto nearest_to = [&](const model::Point3f& target) {
    float best = 1e9f;
    for (const model::Point3f& p : scan.points) best = std::min(best, (p - target).norm());
    return best;
  };
  CHECK(nearest_to({4.2f, 0.0f, 0.2f}) < 0.05f);
  CHECK(nearest_to({0.27f, 3.0f, 0.2f}) < 0.05f);
  const CliResult missing =
      run_cli({"simulate", source_path("rigs/elektron.yaml"), "--scene", "nowhere/lab.yaml"});
  CHECK(missing.exit_code == 2);
  CHECK(missing.err.find("--scene") != std::string::npos);
}

TEST_CASE("simulate and filter refuse an unknown scene") {
  CHECK(run_cli({"simulate", source_path("rigs/elektron.yaml"), "--scene", "moon"}).exit_code == 2);
  const CliResult result =
      run_cli({"filter", "--rig", source_path("rigs/elektron.yaml"), "--scene", "moon"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--scene") != std::string::npos);
}
