#pragma once
// What `costmap` found: each run of the robot through a scenario with one variant of the
// obstacle layer and memory (its outcome, clearance, goals, update and planner times, the
// sensors' timing), as the summary JSON and the text the command prints, and the comparison
// table of `--compare`.
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "rigdesign/scenarios/scenario_runner.hpp"

namespace rigdesign::report {

/// What every run of one `costmap` command shares.
struct CostmapContext {
  std::string rig_name;
  std::vector<std::string> mount_ids;  ///< in the rig's order, as the run's timings are
  std::string scenario;                ///< as named on the command line
  std::uint64_t seed = 1;
};

/// One run: the variant (layer, Hit Layer, the sources' observation persistence), the
/// parameters it ran with, its result and what it wrote.
struct CostmapRun {
  std::string label;  ///< e.g. "voxel + Hit Layer"
  std::string layer;  ///< obstacle or voxel
  bool hit_layer = true;
  bool persistence = false;
  scenarios::ScenarioParams params;
  scenarios::ScenarioResult result;
  std::string folder;
  int frames = 0;
};

/// "collision with wall at t = 3.20 s (...)", or how the run ended without one.
std::string outcome_text(const scenarios::ScenarioResult& result);
/// The run's summary.json (one element of comparison.json).
nlohmann::json costmap_run_json(const CostmapContext& context, const CostmapRun& run);
void print_costmap_run(const CostmapRun& run, std::ostream& out);
/// `--compare`'s table: one row per variant.
void print_costmap_comparison(const std::vector<CostmapRun>& runs, std::ostream& out);

}  // namespace rigdesign::report
