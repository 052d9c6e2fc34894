// Costmap scenario files (issue 35 item 5): the bundled lab scenario read field by field, and
// located errors for bad ones.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/io/scene/scenario_file_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/input_errors.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

const std::string kScenarioCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n";

// A scene with one box, and a scenario beside it whose body is `text`.
std::string scenario_file(const TempFolder& folder, const std::string& text) {
  folder.write("cube.obj", kScenarioCubeObj);
  folder.write("box.yaml",
               "name: box\nrobot_start: {xyz: [0.5, -1, 0], yaw_deg: 90}\n"
               "static:\n  - {name: box, mesh: cube.obj}\n"
               "moving:\n  - name: walker\n    mesh: cube.obj\n"
               "    ellipse: {semi_axes: [2, 1], period: 10}\n    gives_way_within: 0.8\n");
  return folder.write("run.scenario.yaml", text);
}

}  // namespace

TEST_CASE("scenario file: every field as written, the scene's start by default", "[scenario]") {
  TempFolder folder;
  const std::string path = scenario_file(folder, R"(name: round
scene: box.yaml
route:
  - {name: a, xy: [2, 0]}
  - {xy: [3, 1.5], wait: 2}
drops:
  - {name: well, low: [4, -1], high: [5, 1]}
skip_unreachable: true
max_duration: 45
sensing: {min_obstacle_height: 0.03, negative_obstacles: true, camera_decimation: 4, lidar_decimation: 1}
)");
  const scenarios::ScenarioDefinition scenario = io::load_scenario_file(path);
  CHECK(scenario.name == "round");
  CHECK(scenario.scene.objects.size() == 1);
  REQUIRE(scenario.scene.moving.size() == 1);
  CHECK(scenario.scene.moving[0].gives_way_within == 0.8);
  // The scene's robot_start: (0.5, -1) facing +y.
  CHECK(scenario.start.position.x() == Approx(0.5));
  CHECK(scenario.start.position.y() == Approx(-1.0));
  CHECK(scenario.start.yaw == Approx(std::numbers::pi / 2));
  REQUIRE(scenario.route.size() == 2);
  CHECK(scenario.route[0].name == "a");
  CHECK(scenario.route[0].wait == 0.0);
  CHECK(scenario.route[1].position.x() == 3.0);
  CHECK(scenario.route[1].position.y() == 1.5);
  CHECK(scenario.route[1].wait == 2.0);
  REQUIRE(scenario.drops.size() == 1);
  CHECK(scenario.drops[0].contains({4.5, 0.0}));
  CHECK_FALSE(scenario.drops[0].contains({3.9, 0.0}));
  CHECK(scenario.skip_unreachable);
  CHECK(scenario.max_duration == 45.0);
  CHECK(scenario.min_obstacle_height == 0.03);
  CHECK(scenario.negative_obstacles == true);
  CHECK(scenario.camera_decimation == 4);
  CHECK(scenario.lidar_decimation == 1);
}

TEST_CASE("scenario file: the bundled lab scenario", "[scenario]") {
  const scenarios::ScenarioDefinition scenario =
      io::load_scenario_file(source_path("rigs/scenes/lab/lab_goals.scenario.yaml"));
  CHECK(scenario.name == "lab_goals");
  CHECK(scenario.scene.name == "lab");
  REQUIRE(scenario.route.size() == 3);
  CHECK(scenario.route[1].name == "behind the table");
  CHECK(scenario.route[1].wait == 1.0);
  CHECK(scenario.start.position.x() == -1.2);
  CHECK(scenario.start.yaw == 0.0);
  for (const model::MovingObject& walker : scenario.scene.moving)
    CHECK(walker.gives_way_within == 1.2);
}

TEST_CASE("scenario file: bad fields are named with their line and column", "[scenario]") {
  TempFolder folder;
  SECTION("a missing scene file") {
    const std::string path =
        scenario_file(folder, "name: x\nscene: nowhere.yaml\nroute:\n  - {xy: [1, 1]}\n");
    const std::string message = input_error_of([&] { io::load_scenario_file(path); });
    CHECK(message.find(path + ":2:8: scene:") != std::string::npos);
    CHECK(message.find("does not exist") != std::string::npos);
  }
  SECTION("a drop whose high corner is not above its low one") {
    const std::string path =
        scenario_file(folder,
                      "name: x\nscene: box.yaml\nroute:\n  - {xy: [1, 1]}\ndrops:\n"
                      "  - {name: w, low: [1, 1], high: [2, 0.5]}\n");
    const std::string message = input_error_of([&] { io::load_scenario_file(path); });
    CHECK(message.find(path + ":6:") != std::string::npos);
    CHECK(message.find("high") != std::string::npos);
  }
  SECTION("a stride of 0, an unknown key, a goal without xy") {
    const std::string path = scenario_file(
        folder,
        "name: x\nscene: box.yaml\nroute:\n  - {name: g}\nsensing: {lidar_decimation: 0}\n"
        "speed: 3\n");
    const std::string message = input_error_of([&] { io::load_scenario_file(path); });
    CHECK(message.find("lidar_decimation") != std::string::npos);
    CHECK(message.find(":4:") != std::string::npos);  // the goal's line: xy missing
    CHECK(message.find("speed") != std::string::npos);
  }
  SECTION("an error inside the scene file names the scene file") {
    folder.write("broken.yaml", "name: b\nstatic:\n  - {name: q, mesh: missing.obj}\n");
    const std::string path =
        folder.write("run.scenario.yaml", "name: x\nscene: broken.yaml\nroute: [{xy: [1, 1]}]\n");
    const std::string message = input_error_of([&] { io::load_scenario_file(path); });
    CHECK(message.find("broken.yaml:3:") != std::string::npos);
  }
}
