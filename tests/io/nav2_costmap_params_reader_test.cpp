// The nav2 costmap parameter file: values as the file's text gives them, defaults where it
// is silent, and bad input located at the file's own keys.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using rigdesign::test::file_text;
using rigdesign::test::line_of;
using rigdesign::test::TempFolder;

namespace {

const std::string kBundled =
    std::string(RIGDESIGN_SOURCE_DIR) + "/rigs/costmap/ur_cleaner_local_costmap.yaml";

// The first diagnostic of loading `text`, which must fail.
model::Diagnostic failure_of(const std::string& text) {
  TempFolder folder;
  const std::string path = folder.write("costmap.yaml", text);
  try {
    deploy::load_costmap_params(path, {}, {});
  } catch (const model::InputError& error) {
    REQUIRE_FALSE(error.diagnostics().empty());
    return error.diagnostics().front();
  }
  FAIL("no InputError for:\n" << text);
  return {};
}

}  // namespace

TEST_CASE("the bundled nav2 file gives the values its text states", "[io][costmap]") {
  const deploy::CostmapParamsFile file = deploy::load_costmap_params(kBundled, {}, {});
  const costmap::CostmapParams& p = file.costmap;
  CHECK(p.resolution == 0.05);
  CHECK(p.size_x == 6.0);
  CHECK(p.size_y == 6.0);
  CHECK(p.robot_radius == 0.45);
  CHECK(p.inflation.inscribed_radius == 0.45);
  CHECK(p.layer == costmap::ObstacleLayerKind::obstacle);  // plugins lists obstacle_layer
  CHECK(p.use_hit_layer);
  CHECK(p.hit.hit == 3);
  CHECK(p.hit.hit_max == 1500);
  CHECK(p.hit.d_threshold == 0.0001);
  CHECK(p.hit.d_duration == 10.0);
  CHECK(p.inflation.inflation_radius == 0.55);
  CHECK(p.inflation.cost_scaling_factor == 3.0);
  CHECK_FALSE(p.inflation.inflate_unknown);
  CHECK(p.voxel.z_min == 0.0);
  CHECK(p.voxel.z_max == Approx(40 * 0.05));  // origin_z + z_voxels x z_resolution
  CHECK(p.voxel.unknown_threshold == 4);
  REQUIRE(file.sources.size() == 5);
  CHECK(file.sources.front().name == "front_camera");
  CHECK(file.sources.back().name == "top_lidar");
  for (const costmap::NamedObservationSource& named : file.sources) {
    CHECK(named.source.min_obstacle_height == 0.10);
    CHECK(named.source.max_obstacle_height == 1.0);
    CHECK(named.source.obstacle_max_range == 2.5);
    CHECK(named.source.raytrace_max_range == 3.0);
  }
}

TEST_CASE("keys the file does not give keep the caller's defaults", "[io][costmap]") {
  TempFolder folder;
  const std::string path =
      folder.write("flat.yaml",
                   "resolution: 0.1\n"
                   "plugins: [voxel_layer, inflation_layer]\n"
                   "voxel_layer:\n"
                   "  plugin: nav2_costmap_2d::VoxelLayer\n"
                   "  observation_sources: [lidar]\n"
                   "  lidar: {clearing: false}\n"
                   "inflation_layer: {plugin: nav2_costmap_2d::InflationLayer}\n");
  costmap::CostmapParams defaults;
  defaults.size_x = 7.0;
  defaults.hit.hit_max = 99;
  costmap::ObservationSource source_defaults;
  source_defaults.obstacle_max_range = 4.0;
  const deploy::CostmapParamsFile file =
      deploy::load_costmap_params(path, defaults, source_defaults);
  CHECK(file.costmap.resolution == 0.1);
  CHECK(file.costmap.size_x == 7.0);
  CHECK(file.costmap.hit.hit_max == 99);
  CHECK(file.costmap.layer == costmap::ObstacleLayerKind::voxel);
  CHECK_FALSE(file.costmap.use_hit_layer);  // not in plugins
  REQUIRE(file.sources.size() == 1);
  CHECK_FALSE(file.sources[0].source.clearing);
  CHECK(file.sources[0].source.marking);
  CHECK(file.sources[0].source.obstacle_max_range == 4.0);
}

TEST_CASE("bad costmap parameters are reported at the file's keys", "[io][costmap]") {
  const std::string good = file_text(kBundled);
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
  };
  SECTION("a misspelt key gets a suggestion") {
    const std::string text = with("        hit_max: 1500", "        hit_maxx: 1500");
    const model::Diagnostic d = failure_of(text);
    CHECK(d.field == "local_costmap.local_costmap.ros__parameters.hit_layer.hit_maxx");
    CHECK(d.where.line == line_of(text, "hit_maxx"));
    CHECK(d.expected.find("hit_max") != std::string::npos);
  }
  SECTION("a ceiling below the step fails the costmap's own check, at hit_max") {
    const std::string text = with("        hit_max: 1500", "        hit_max: 2");
    const model::Diagnostic d = failure_of(text);
    CHECK(d.field == "local_costmap.local_costmap.ros__parameters.hit_layer.hit_max");
    CHECK(d.where.line == line_of(text, "hit_max: 2"));
  }
  SECTION("a number that is not one") {
    const std::string text = with("      resolution: 0.05", "      resolution: fine");
    const model::Diagnostic d = failure_of(text);
    CHECK(d.field == "local_costmap.local_costmap.ros__parameters.resolution");
    CHECK(d.where.line == line_of(text, "resolution: fine"));
  }
  SECTION("a named source without its parameters") {
    const std::string text =
        with("observation_sources: front_camera", "observation_sources: bumper front_camera");
    const model::Diagnostic d = failure_of(text);
    CHECK(d.field.find("obstacle_layer.bumper") != std::string::npos);
  }
  SECTION("both obstacle layers at once") {
    const std::string text = with("[\"obstacle_layer\",", "[\"obstacle_layer\", \"voxel_layer\",");
    const model::Diagnostic d = failure_of(text);
    CHECK(d.field == "local_costmap.local_costmap.ros__parameters.plugins");
  }
}

TEST_CASE("costmap --params runs the file and exits 2 on a bad one", "[cli][costmap]") {
  TempFolder folder;
  std::string text = file_text(kBundled);
  text.replace(text.find("cost_scaling_factor: 3.0"), 24, "cost_scaling_factor: -1");
  const std::string bad = folder.write("bad.yaml", text);
  const test::CliResult result =
      test::run_cli({"costmap", "--rig", "rigs/ur_cleaner.yaml", "--scenario", "stationary",
                     "--params", bad, "--out", folder.path() + "/out"});
  CHECK(result.exit_code == 2);
  const std::string where = bad + ":" + std::to_string(line_of(text, "cost_scaling_factor: -1"));
  CHECK(result.err.find(where) != std::string::npos);
  CHECK(result.err.find("inflation_layer.cost_scaling_factor") != std::string::npos);
}
