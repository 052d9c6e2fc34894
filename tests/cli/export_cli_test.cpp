// Issue 14: `rigdesign export` writes the three files, and the nav2 file it writes runs in
// rigdesign's own costmap scenario: with its Hit Layer values the UR Cleaner passes the
// foam-topped table of paper 1's Fig. 12 on the 2D obstacle layer, without them it hits it.
#include <catch2/catch.hpp>
#include <filesystem>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

TEST_CASE("export CLI: files, and the exported Hit Layer avoids the Fig. 12 collision",
          "[deploy][scenario]") {
  TempFolder folder;
  const std::string out = folder.path() + "/ur_cleaner";
  const CliResult result = run_cli({"export", source_path("rigs/ur_cleaner.yaml"), "--to", out});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  for (const char* name : {"sensors.urdf.xacro", "nav2_costmap.yaml", "self_filters.yaml"})
    CHECK(std::filesystem::exists(out + "/" + name));
  CHECK(result.out.find("Hit Layer: hit") != std::string::npos);
  const auto run = [&](bool hit_layer) {
    std::vector<std::string> args = {"costmap", "--rig", source_path("rigs/ur_cleaner.yaml"),
                                     "--scenario", "wall_following", "--params",
                                     out + "/nav2_costmap.yaml", "--layer", "obstacle",
                                     "--frame-every", "0", "--out", folder.path() + "/run"};
    if (!hit_layer) args.push_back("--no-hit-layer");
    return run_cli(args);
  };
  const CliResult with_hit = run(true);
  INFO(with_hit.err);
  REQUIRE(with_hit.exit_code == 0);
  CHECK(with_hit.out.find("collision: none; goal reached") != std::string::npos);
  // The same outcome as the scenario's built-in parameters (paper 1's Hit Layer values).
  const CliResult defaults =
      run_cli({"costmap", "--rig", source_path("rigs/ur_cleaner.yaml"), "--scenario",
               "wall_following", "--frame-every", "0", "--out", folder.path() + "/defaults"});
  CHECK(defaults.out.find("collision: none; goal reached") != std::string::npos);
  const CliResult without = run(false);
  CHECK(without.out.find("collision: collision with foam") != std::string::npos);
}

TEST_CASE("export CLI: bad options exit 2 naming the option", "[deploy]") {
  TempFolder folder;
  const CliResult speed = run_cli({"export", source_path("rigs/ur_cleaner.yaml"), "--to",
                                   folder.path(), "--min-speed", "0"});
  CHECK(speed.exit_code == 2);
  CHECK(speed.err.find("--min-speed") != std::string::npos);
  const CliResult parent = run_cli({"export", source_path("rigs/turtlebot4.yaml"), "--to",
                                    folder.path(), "--parent", "nowhere"});
  CHECK(parent.exit_code == 2);
  CHECK(parent.err.find("no link 'nowhere'") != std::string::npos);
  CHECK(folder.entries() == 0);
}
