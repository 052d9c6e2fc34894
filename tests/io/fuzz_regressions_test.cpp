// Inputs the fuzz targets (fuzz/, docs/fuzzing.md) found crashing a reader, kept as tests:
// each must now be refused with an InputError that names the file, like any bad input.
#include <catch2/catch.hpp>
#include <filesystem>
#include <functional>
#include <map>

#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/io/cloud/cloud_io.hpp"
#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;

namespace {

// Reader per fuzz target, as the target calls it.
const std::map<std::string, std::function<void(const std::string&)>>& readers() {
  static const std::map<std::string, std::function<void(const std::string&)>> table = {
      {"artifacts_json", [](const std::string& path) { io::read_artifacts(path); }},
      {"rig_yaml", [](const std::string& path) { io::load_rig(path); }},
      {"cloud_pcd", [](const std::string& path) { io::read_cloud(path); }},
      {"catalog_yaml", [](const std::string& path) { io::load_catalog(path); }},
      {"costmap_params_yaml",
       [](const std::string& path) {
         deploy::load_costmap_params(path, costmap::CostmapParams{}, costmap::ObservationSource{});
       }},
      {"robot_urdf",
       [](const std::string& path) {
         io::RobotDescriptionRequest request;
         request.path = path;
         request.expander = io::RobotDescriptionRequest::Expander::builtin;
         request.load_meshes = false;
         io::load_robot_description(request);
       }},
  };
  return table;
}

}  // namespace

TEST_CASE("fuzz findings: every reproducer is refused with the file named") {
  const std::filesystem::path root = test::source_path("tests/data/fuzz");
  int reproducers = 0;
  for (const auto& target : std::filesystem::directory_iterator(root)) {
    const std::string name = target.path().filename().string();
    REQUIRE(readers().count(name) == 1);
    for (const auto& input : std::filesystem::directory_iterator(target.path())) {
      const std::string path = input.path().string();
      INFO(name << ": " << path);
      ++reproducers;
      try {
        readers().at(name)(path);
        FAIL("accepted");
      } catch (const model::InputError& error) {
        CHECK(error.diagnostics().front().where.file == path);
      }
    }
  }
  CHECK(reproducers >= 1);
}
