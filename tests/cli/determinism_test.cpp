// Issue 16, determinism: the same inputs and seed give the same files, byte for byte, in two
// fresh processes. Fields that measure this machine's speed are left out by name.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/run_in_child.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

// Timing fields (JSON keys, CSV columns) and the one picture drawn against time per update.
const std::set<std::string> kTimingFields = {"update_ms", "points_per_second"};
const std::set<std::string> kTimingPictures = {"occupancy_pareto.png"};

void drop_timing(nlohmann::json& json) {
  if (json.is_object()) {
    for (const std::string& key : kTimingFields) json.erase(key);
    for (auto& [key, value] : json.items()) drop_timing(value);
  } else if (json.is_array()) {
    for (auto& value : json) drop_timing(value);
  }
}

std::string without_timing_columns(const std::string& csv) {
  std::istringstream lines(csv);
  std::string line, result;
  std::vector<bool> keep;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (keep.empty()) {
      for (const std::string& name : cells) keep.push_back(kTimingFields.count(name) == 0);
    }
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i >= keep.size() || keep[i]) result += cells[i] + ",";
    }
    result += "\n";
  }
  return result;
}

Snapshot comparable(Snapshot files) {
  Snapshot result;
  for (auto& [name, bytes] : files) {
    const std::string file = name.substr(name.find_last_of('/') + 1);
    if (kTimingPictures.count(file) != 0) continue;
    if (name.size() > 5 && name.substr(name.size() - 5) == ".json") {
      nlohmann::json json = nlohmann::json::parse(bytes);
      drop_timing(json);
      bytes = json.dump();
    } else if (name.size() > 4 && name.substr(name.size() - 4) == ".csv") {
      bytes = without_timing_columns(bytes);
    }
    result[name] = bytes;
  }
  return result;
}

// Runs `args` (with "{out}" for the output folder) twice into the same folder (outputs name
// their own paths) and compares what each run left there.
void check_twice(const std::vector<std::string>& args) {
  TempFolder folder;
  const std::string out = folder.path() + "/out";
  std::vector<std::string> expanded;
  for (const std::string& arg : args) expanded.push_back(arg == "{out}" ? out : arg);
  std::vector<Snapshot> runs;
  for (int run = 0; run < 2; ++run) {
    REQUIRE(run_in_child(expanded) == 0);
    runs.push_back(comparable(snapshot(out)));
  }
  REQUIRE(runs[0].size() >= 2);
  INFO("differing: " << differences(runs[0], runs[1]));
  CHECK(runs[0] == runs[1]);
}

}  // namespace

TEST_CASE("determinism: the main job writes the same files twice") {
  check_twice({"select", "--catalog", source_path("rigs/catalogs/ur_cleaner.yaml"),
               "--requirements", source_path("rigs/requirements/ur_cleaner.yaml"), "--policy",
               source_path("rigs/policies/ur_cleaner.yaml"), "--budget", "3000", "--no-renders",
               "--out", "{out}"});
  // The renders' determinism is the coverage kill test's: it compares whole sets of pictures
  // from separate processes byte for byte.
}

TEST_CASE("determinism: simulate with a seed writes the same clouds twice") {
  // Two 2D scanners: the noise and dropout draws are what a seed fixes; a depth camera's
  // 300,000 points per frame add time under the sanitizers, not coverage.
  check_twice({"simulate", source_path("rigs/cart_two_scanners.yaml"), "--scene", "corridor",
               "--frames", "3", "--seed", "7", "--dropout", "0.1", "--out", "{out}"});
}

TEST_CASE("determinism: occupancy writes the same scores twice") {
  check_twice({"occupancy", "--rig", source_path("rigs/cell.yaml"), "--duration", "2", "--voxels",
               "0.1", "--persistence", "none", "--out", "{out}"});
}

TEST_CASE("determinism: localize on a scenario writes the same log, truth and plots twice") {
  check_twice(
      {"localize", "--scenario", "corner", "--seed", "3", "--checkpoints", "5", "--out", "{out}"});
}
