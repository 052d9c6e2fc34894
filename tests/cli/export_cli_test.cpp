// Issues 14 and 30: `rigdesign export` writes the three files, and the nav2 file it writes
// runs in rigdesign's own costmap scenario: with its blind-gap memory (nav2's
// observation_persistence by default, paper 1's Hit Layer when asked for) the UR Cleaner
// passes the foam-topped table of paper 1's Fig. 12 on the 2D obstacle layer, without it it
// hits the foam at about 7 s as in the paper. The persistence value itself is checked against
// a hand computation in tests/deploy/blind_memory_test.cpp.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

std::string exported_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("export CLI: files, and the exported blind-gap memory avoids the Fig. 12 collision",
          "[deploy][scenario]") {
  TempFolder folder;
  const std::string out = folder.path() + "/ur_cleaner";
  const CliResult result = run_cli({"export", source_path("rigs/ur_cleaner.yaml"), "--to", out});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  for (const char* name : {"sensors.urdf.xacro", "nav2_costmap.yaml", "self_filters.yaml"})
    CHECK(std::filesystem::exists(out + "/" + name));
  // By default nothing outside nav2: the memory is nav2's observation_persistence.
  const std::string params = exported_text(out + "/nav2_costmap.yaml");
  CHECK(params.find("hit_layer") == std::string::npos);
  CHECK(params.find("observation_persistence: 5.8") != std::string::npos);
  const auto run = [&](const std::string& params_file, const std::string& flag) {
    std::vector<std::string> args = {"costmap",
                                     "--rig",
                                     source_path("rigs/ur_cleaner.yaml"),
                                     "--scenario",
                                     "wall_following",
                                     "--params",
                                     params_file,
                                     "--layer",
                                     "obstacle",
                                     "--frame-every",
                                     "0",
                                     "--out",
                                     folder.path() + "/run"};
    if (!flag.empty()) args.push_back(flag);
    return run_cli(args);
  };
  // Paper 1's Fig. 12 outcome on the 2D layer: the foam hit at about 7 s without memory.
  const CliResult with_memory = run(out + "/nav2_costmap.yaml", "");
  INFO(with_memory.err);
  REQUIRE(with_memory.exit_code == 0);
  CHECK(with_memory.out.find("observation persistence") != std::string::npos);
  CHECK(with_memory.out.find("collision: none; goal reached") != std::string::npos);
  const CliResult without = run(out + "/nav2_costmap.yaml", "--no-memory");
  CHECK(without.out.find("collision: collision with foam at t = 7.") != std::string::npos);
  // A team that built paper 1's Hit Layer asks for it by class: the same outcome.
  const std::string hit_out = folder.path() + "/with_hit";
  REQUIRE(run_cli({"export", source_path("rigs/ur_cleaner.yaml"), "--to", hit_out,
                   "--hit-layer-plugin", "ur_cleaner_layers::HitLayer"})
              .exit_code == 0);
  const std::string hit_params = exported_text(hit_out + "/nav2_costmap.yaml");
  CHECK(hit_params.find("plugin: \"ur_cleaner_layers::HitLayer\"") != std::string::npos);
  CHECK(hit_params.find("observation_persistence: 5.8") == std::string::npos);
  const CliResult with_hit = run(hit_out + "/nav2_costmap.yaml", "");
  CHECK(with_hit.out.find("+ Hit Layer") != std::string::npos);
  CHECK(with_hit.out.find("collision: none; goal reached") != std::string::npos);
  CHECK(run(hit_out + "/nav2_costmap.yaml", "--no-hit-layer")
            .out.find("collision: collision with foam") != std::string::npos);
}

TEST_CASE("export CLI: --hit-layer-plugin takes a pluginlib class name", "[deploy]") {
  TempFolder folder;
  for (const char* bad : {"HitLayer", "::HitLayer", "pkg::", "pkg::Hit Layer", "pkg/"}) {
    INFO(bad);
    const CliResult result = run_cli({"export", source_path("rigs/ur_cleaner.yaml"), "--to",
                                      folder.path() + "/out", "--hit-layer-plugin", bad});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("--hit-layer-plugin") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(folder.path() + "/out"));
  }
}

TEST_CASE("export CLI: bad options exit 2 naming the option", "[deploy]") {
  TempFolder folder;
  const CliResult speed = run_cli(
      {"export", source_path("rigs/ur_cleaner.yaml"), "--to", folder.path(), "--min-speed", "0"});
  CHECK(speed.exit_code == 2);
  CHECK(speed.err.find("--min-speed") != std::string::npos);
  const CliResult parent = run_cli({"export", source_path("rigs/turtlebot4.yaml"), "--to",
                                    folder.path(), "--parent", "nowhere"});
  CHECK(parent.exit_code == 2);
  CHECK(parent.err.find("no link 'nowhere'") != std::string::npos);
  CHECK(folder.entries() == 0);
}
