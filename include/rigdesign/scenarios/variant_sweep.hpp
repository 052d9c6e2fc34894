#pragma once
/// Paper 2's Table 1 for any rig (issue 35 item 3): the same scenario driven by subsets of the
/// rig's mounts over many seeds, each subset at its critical distance, the smallest clearance
/// margin (costmap footprint padding) at which none of its runs collides.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"

namespace rigdesign::scenarios {

/// A subset of a rig's mounts, by index in rig.mounts.
struct RigVariant {
  std::string label;  ///< "kinect + front_scanner", "kinect only"
  std::vector<std::size_t> mounts;
};

/// The whole rig, every subset without one mount (N-1), and every mount alone, each once, in
/// that order (for two mounts: both, then each alone).
std::vector<RigVariant> rig_variants(const model::Rig& rig);

/// `rig` with only the mounts of `variant`.
model::Rig rig_with(const model::Rig& rig, const RigVariant& variant);

/// `params` for a subset of a rig's mounts: when none of the subset's sources clears (paper 2's
/// lidar, which only marks, driving alone), each of them clears too; a costmap no source clears
/// keeps every mark for ever, and the trails of people walking by close the office. Sets
/// `clearing_added` when it did so.
ScenarioParams params_for_subset(const model::Rig& subset, ScenarioParams params,
                                 bool& clearing_added);

/// One run's outcome, without its trajectory.
struct RunSummary {
  std::uint64_t seed = 0;
  double margin = 0.0;  ///< [m]
  bool collided = false;
  std::string collision_object;
  double collision_time = 0.0;  ///< [s]
  int goals_reached = 0;
  int goals_refused = 0;
  std::size_t goals = 0;
  double average_speed = 0.0;     ///< [m/s] on the legs to goals reached
  double reached_distance = 0.0;  ///< [m] driven on those legs
  double reached_seconds = 0.0;   ///< [s] they took
  double recovery_seconds = 0.0;  ///< [s]
  int recoveries = 0;
  bool drove_off = false;
  std::string drop_name;
  double drove_off_speed = 0.0;  ///< [m/s]
  double end_time = 0.0;         ///< [s]
};

RunSummary summarize_run(std::uint64_t seed, double margin, const ScenarioResult& result);

struct SweepSettings {
  /// [m] clearance margins tried in ascending order; paper 2 reports its critical distances
  /// in 5 cm steps (5 cm, 20 cm), so 0 to 0.30 m by 0.05 m.
  std::vector<double> margins = {0.0, 0.05, 0.10, 0.15, 0.20, 0.25, 0.30};
  int seeds = 20;                ///< paper 2's 20 repeats
  std::uint64_t first_seed = 1;  ///< seeds first_seed .. first_seed + seeds - 1
  int threads = 1;               ///< runs in parallel (each run is deterministic on its own)
};

struct VariantOutcome {
  RigVariant variant;
  /// Not run: none of its mounts can mark the costmap (the InputError's message).
  std::string skipped;
  /// None of its mounts' sources cleared, so they were made to (params_for_subset).
  bool clearing_added = false;
  /// [m] the smallest margin at which no seed collided; none when every margin tried collided.
  std::optional<double> critical_distance;
  /// The runs at the critical distance (every seed), or at the largest margin when none.
  std::vector<RunSummary> runs;
  /// For each margin below the critical distance, the lowest seed that collided there.
  std::vector<RunSummary> failures;
  /// For each margin run, in order (up to the critical distance), whether each seed's run
  /// collided there, in seed order: the data of the bootstrap over seeds (seed_bootstrap.hpp).
  /// A seed clear at one margin may collide at a larger one, so a seed has no critical
  /// distance of its own.
  std::vector<std::vector<bool>> collided_by_margin;
  int runs_made = 0;  ///< all runs of the sweep
};

/// Builds the scenario for a seed and a body radius [m] (make_costmap_scenario's arguments; a
/// scenario file ignores them).
using ScenarioFactory = std::function<ScenarioDefinition(std::uint64_t seed, double body_radius)>;

/// Runs the scenario `make_scenario` builds with `variant`'s mounts (params.seed and the
/// scenario's layout both take the seed): for each margin in order, every seed, until a
/// margin at which no seed collides (the critical distance). Every seed runs at every margin up
/// to it, so that a bootstrap over the seeds can find each resample's own critical distance.
/// Seeds run in batches of `threads`; `on_run` is called after each run, from the calling
/// thread. Deterministic for the settings, whatever the thread count.
VariantOutcome sweep_variant(const ScenarioFactory& make_scenario, const model::Rig& rig,
                             const model::SensorLibrary& library, const ScenarioParams& params,
                             const RigVariant& variant, const SweepSettings& settings,
                             const std::function<void(const RunSummary&)>& on_run = {});

/// Over runs: the average speed pooled (all legs to goals reached, distance over time, so a
/// run that reached none adds nothing rather than a zero); the rest means per run.
struct VariantMeans {
  double average_speed = 0.0;  ///< [m/s]
  double goals_reached = 0.0;
  double goals_refused = 0.0;
  double recovery_seconds = 0.0;
  int drove_off = 0;  ///< runs that drove off a drop
};
VariantMeans means_of(const std::vector<RunSummary>& runs);

}  // namespace rigdesign::scenarios
