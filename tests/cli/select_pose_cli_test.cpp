// Issue 15 through the CLI: pose ranges in catalog slots, --robust, and their bad input.
#include <stdlib.h>
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

// A front camera whose pitch the search chooses, a second front camera high up, a bumper
// scanner; small robot, coarse angles so that the whole command runs in a test.
std::string pose_catalog(const std::string& front_pitch) {
  return "name: Poses\nsensor_library: " + source_path("sensors.yaml") + R"(
body: {radius: 0.3, height: 0.8}
distance_of_interest: 2.5
reference_machine: test
filtering_seconds_per_point: 3.5e-7
sensors:
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
  - {sensor: pmd_pico_flexx, modes: [mode_9_15fps]}
  - {sensor: rplidar_a2m8, modes: [10hz]}
slots:
  - id: front
    pose: {xyz: [0.31, 0, 0.4], rpy_deg: [0, )" +
         front_pitch + R"(, 0]}
    recessed: true
    allows: [realsense_d435, pmd_pico_flexx]
  - id: front_high
    pose: {xyz: [0.31, 0, 0.7], rpy_deg: [0, {min: 20, max: 40, step: 10}, 0]}
    recessed: true
    allows: [realsense_d435]
  - {id: bumper, pose: {xyz: [0.31, 0, 0.15]}, recessed: true, allows: [rplidar_a2m8]}
transfer:
  - {id: onboard, capacity_bps: 3.0e9, price_usd: 0}
cpus:
  - {id: small, cores: 3.0, price_usd: 300}
  - {id: big, cores: 8.0, price_usd: 800}
)";
}

const char* const kPoseRequirements = R"(name: Poses app
body: {radius: 0.3, height: 0.8}
sectors:
  - {name: front, from_deg: -10, to_deg: 10, min_complete_coverage: 0.3, min_floor_coverage: 0.5}
range: {distance: 2.5}
robot_speed: {max_speed: 1.0, max_travel_between_frames: 0.1}
lighting: [dark, indoor]
)";

struct PoseSetup {
  TempFolder folder;
  std::string catalog, requirements, out;
  explicit PoseSetup(const std::string& front_pitch = "{min: 0, max: 40, step: 10}",
                     const std::string& requirements_text = kPoseRequirements) {
    catalog = folder.write("catalog.yaml", pose_catalog(front_pitch));
    requirements = folder.write("req.yaml", requirements_text);
    out = folder.path() + "/out";
  }
  CliResult select(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args = {"select",     "--catalog",    catalog, "--requirements",
                                     requirements, "--budget",     "20000", "--step",
                                     "10",         "--no-renders", "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_cli(args);
  }
};

// chosen_rig.yaml without the mount at `index`, written beside it.
std::string without_mount(const std::string& rig_file, std::size_t index) {
  YAML::Node rig = YAML::LoadFile(rig_file);
  YAML::Node kept(YAML::NodeType::Sequence);
  for (std::size_t i = 0; i < rig["mounts"].size(); ++i)
    if (i != index) kept.push_back(rig["mounts"][i]);
  rig["mounts"] = kept;
  const std::string path = rig_file + ".without" + std::to_string(index) + ".yaml";
  std::ofstream(path) << YAML::Dump(rig) << '\n';
  return path;
}

}  // namespace

TEST_CASE("select with pose ranges writes the chosen poses, a margin plot, and check agrees") {
  PoseSetup setup;
  const CliResult result = setup.select();
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  CHECK(result.out.find("front: ") != std::string::npos);
  CHECK(result.out.find(" at pitch ") != std::string::npos);
  CHECK(result.out.find("refined poses: ") != std::string::npos);
  // The rig written is checked on the exact path by an independent command.
  const CliResult check = run_cli({"check", setup.out + "/chosen_rig.yaml"});
  INFO(check.out);
  CHECK(check.exit_code == 0);
  // Its front camera's pitch lies in the slot's range, 0 to 40 deg: REP-103 pitch of the
  // written pose, read back from the file's rpy_deg.
  const YAML::Node rig = YAML::LoadFile(setup.out + "/chosen_rig.yaml");
  bool front_found = false;
  for (const YAML::Node& mount : rig["mounts"]) {
    if (mount["id"].as<std::string>() != "front") continue;
    front_found = true;
    const double pitch = mount["pose"]["rpy_deg"][1].as<double>();
    CHECK(pitch >= -1e-9);
    CHECK(pitch <= 40 + 1e-9);
  }
  if (front_found) CHECK(std::filesystem::exists(setup.out + "/margin_front_pitch.png"));
  CHECK(std::filesystem::exists(setup.out + "/pareto.png"));
}

TEST_CASE("select --robust n-1: every single failure leaves a rig check accepts") {
  PoseSetup setup;
  const CliResult plain = setup.select();
  REQUIRE(plain.exit_code == 0);
  const CliResult robust = setup.select({"--robust", "n-1"});
  INFO(robust.out << robust.err);
  REQUIRE(robust.exit_code == 0);
  CHECK(robust.out.find("survives: ") != std::string::npos);
  CHECK(robust.out.find("robustness costs ") != std::string::npos);
  // Independently: drop each mount of the robust rig in turn; `check` must still pass the
  // same front sector (the requirement states no relaxed set, so the thresholds stay).
  const std::string rig_file = setup.out + "/chosen_rig.yaml";
  const std::size_t mounts = YAML::LoadFile(rig_file)["mounts"].size();
  REQUIRE(mounts >= 2);
  for (std::size_t i = 0; i < mounts; ++i) {
    const CliResult check = run_cli({"check", without_mount(rig_file, i)});
    INFO("without mount " << i << "\n" << check.out << check.err);
    CHECK(check.exit_code == 0);
  }
}

TEST_CASE("select: pose range and --robust bad input is exit 2 naming the field") {
  SECTION("a step that does not divide the range") {
    PoseSetup setup("{min: 0, max: 40, step: 15}");
    const CliResult result = setup.select();
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("catalog.yaml:13:") != std::string::npos);
    CHECK(result.err.find("slots[0].pose.rpy_deg[1].step") != std::string::npos);
  }
  SECTION("min above max") {
    PoseSetup setup("{min: 40, max: 0, step: 10}");
    const CliResult result = setup.select();
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("slots[0].pose.rpy_deg[1].min") != std::string::npos);
  }
  SECTION("a step of zero") {
    PoseSetup setup("{min: 0, max: 40, step: 0}");
    const CliResult result = setup.select();
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("slots[0].pose.rpy_deg[1].step") != std::string::npos);
  }
  SECTION("--robust with an unknown condition") {
    PoseSetup setup;
    const CliResult result = setup.select({"--robust", "moonlight"});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("--robust") != std::string::npos);
  }
  SECTION("--robust with the same failure twice, or two lighting conditions (issue 32)") {
    PoseSetup setup;
    const CliResult twice = setup.select({"--robust", "n-1", "--robust", "n-1"});
    CHECK(twice.exit_code == 2);
    CHECK(twice.err.find("--robust: gives n-1 twice") != std::string::npos);
    const CliResult two = setup.select({"--robust", "dark", "--robust", "sunlight"});
    CHECK(two.exit_code == 2);
    CHECK(two.err.find("--robust: names a second lighting condition ('sunlight')") !=
          std::string::npos);
  }
}

TEST_CASE("select --robust n-1 with a catalog of one slot is exit 2") {
  TempFolder folder;
  const std::string catalog =
      folder.write("one.yaml", "name: One\nsensor_library: " + source_path("sensors.yaml") + R"(
body: {radius: 0.3, height: 0.8}
distance_of_interest: 2.5
reference_machine: test
filtering_seconds_per_point: 0
sensors:
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
slots:
  - {id: front, pose: {xyz: [0.31, 0, 0.4], rpy_deg: [0, 20, 0]}, recessed: true, allows: [realsense_d435]}
transfer:
  - {id: onboard, capacity_bps: 3.0e9, price_usd: 0}
cpus:
  - {id: small, cores: 3.0, price_usd: 300}
)");
  const std::string requirements = folder.write("req.yaml", kPoseRequirements);
  const CliResult result =
      run_cli({"select", "--catalog", catalog, "--requirements", requirements, "--budget", "5000",
               "--robust", "n-1", "--step", "10", "--no-renders", "--out", folder.path() + "/out"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--robust") != std::string::npos);
  CHECK(result.err.find("one sensor cannot survive its failure") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(folder.path() + "/out"));
}

TEST_CASE(
    "select --robust n-1 reports every phase: its end on standard error, a line in the report") {
  // Issue 32: after the search "about 1 s left" was followed by a minute of silence. Every
  // phase now ends with its own line (RIGDESIGN_PROGRESS=1: the CI log form) and has a
  // summary line in the report, in the order they ran.
  PoseSetup setup;
  ::setenv("RIGDESIGN_PROGRESS", "1", 1);
  const CliResult result = setup.select({"--robust", "n-1"});
  ::unsetenv("RIGDESIGN_PROGRESS");
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  const std::vector<std::string> phases = {"search", "exact verification",
                                           "exact verification of failures", "pose refinement",
                                           "robustness cost"};
  std::size_t at_err = 0;
  std::size_t at_out = 0;
  for (const std::string& phase : phases) {
    INFO(phase);
    at_err = result.err.find("select #0: " + phase + ": ", at_err);
    CHECK(at_err != std::string::npos);
    CHECK(result.err.find("(100 %), ", at_err) != std::string::npos);
    at_out = result.out.find("    phase " + phase + ": ", at_out);
    CHECK(at_out != std::string::npos);
  }
  CHECK(result.err.find("select: files: ") != std::string::npos);
  CHECK(result.out.find("\nphase files: ") != std::string::npos);
}
