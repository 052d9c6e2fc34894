// Paper 2's Table 1 for any rig: subsets of mounts, seeds, the critical-distance sweep.
#include "rigdesign/scenarios/variant_sweep.hpp"

#include <algorithm>

#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/parallel_for.hpp"

namespace rigdesign::scenarios {
namespace {

std::string label_of(const model::Rig& rig, const std::vector<std::size_t>& mounts) {
  std::string label;
  for (const std::size_t i : mounts) label += (label.empty() ? "" : " + ") + rig.mounts[i].id;
  return mounts.size() == 1 && rig.mounts.size() > 1 ? label + " only" : label;
}

// Seeds [first, first + count) at `margin`, `threads` at a time, in seed order; stops after
// the first batch with a collision. Results in seed order.
std::vector<RunSummary> run_seeds(const ScenarioFactory& make_scenario, const model::Rig& rig,
                                  const model::SensorLibrary& library, const ScenarioParams& params,
                                  double margin, const SweepSettings& settings,
                                  const std::function<void(const RunSummary&)>& on_run) {
  std::vector<RunSummary> runs;
  const int threads = std::max(1, settings.threads);
  for (int start = 0; start < settings.seeds; start += threads) {
    const int batch = std::min(threads, settings.seeds - start);
    std::vector<RunSummary> results(static_cast<std::size_t>(batch));
    model::parallel_for(results.size(), batch, [&](std::size_t j) {
      const std::uint64_t seed = settings.first_seed + static_cast<std::uint64_t>(start) + j;
      ScenarioParams run_params = params;
      run_params.seed = seed;
      run_params.clearance_margin = margin;
      const ScenarioDefinition scenario = make_scenario(seed, rig.body.radius);
      results[j] = summarize_run(seed, margin, run_scenario(scenario, rig, library, run_params));
    });
    bool collided = false;
    for (const RunSummary& run : results) {
      runs.push_back(run);
      if (on_run) on_run(run);
      collided = collided || run.collided;
    }
    if (collided) break;
  }
  return runs;
}

}  // namespace

std::vector<RigVariant> rig_variants(const model::Rig& rig) {
  const std::size_t n = rig.mounts.size();
  std::vector<std::vector<std::size_t>> subsets;
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  subsets.push_back(all);
  if (n > 2) {  // with two mounts the N-1 subsets are the single mounts
    for (std::size_t skip = 0; skip < n; ++skip) {
      std::vector<std::size_t> subset;
      for (std::size_t i = 0; i < n; ++i)
        if (i != skip) subset.push_back(i);
      subsets.push_back(subset);
    }
  }
  if (n > 1) {
    for (std::size_t i = 0; i < n; ++i) subsets.push_back({i});
  }
  std::vector<RigVariant> variants;
  for (const std::vector<std::size_t>& subset : subsets)
    variants.push_back({label_of(rig, subset), subset});
  return variants;
}

model::Rig rig_with(const model::Rig& rig, const RigVariant& variant) {
  model::Rig subset = rig;
  subset.mounts.clear();
  for (const std::size_t i : variant.mounts) subset.mounts.push_back(rig.mounts.at(i));
  return subset;
}

RunSummary summarize_run(std::uint64_t seed, double margin, const ScenarioResult& result) {
  RunSummary run;
  run.seed = seed;
  run.margin = margin;
  run.collided = result.collided;
  run.collision_object = result.collision_object;
  run.collision_time = result.collided ? result.collision_time : 0.0;
  run.goals_reached = result.goals_reached;
  for (const StopOutcome& stop : result.stops) {
    run.goals_refused += stop.refused ? 1 : 0;
    if (!stop.reached) continue;
    run.reached_distance += stop.leg_distance;
    run.reached_seconds += stop.leg_seconds;
  }
  run.goals = result.route_size;
  run.average_speed = result.average_speed;
  run.recovery_seconds = result.recovery_seconds;
  run.recoveries = result.recoveries;
  run.drove_off = result.drove_off;
  run.drop_name = result.drop_name;
  run.drove_off_speed = result.drove_off_speed;
  run.end_time = result.end_time;
  return run;
}

VariantOutcome sweep_variant(const ScenarioFactory& make_scenario, const model::Rig& rig,
                             const model::SensorLibrary& library, const ScenarioParams& params,
                             const RigVariant& variant, const SweepSettings& settings,
                             const std::function<void(const RunSummary&)>& on_run) {
  VariantOutcome outcome;
  outcome.variant = variant;
  const model::Rig subset = rig_with(rig, variant);
  try {
    check_scenario_inputs(subset, library, params);
  } catch (const model::InputError& error) {
    outcome.skipped = error.what();
    return outcome;
  }
  for (const double margin : settings.margins) {
    std::vector<RunSummary> runs =
        run_seeds(make_scenario, subset, library, params, margin, settings, on_run);
    outcome.runs_made += static_cast<int>(runs.size());
    const auto collision =
        std::find_if(runs.begin(), runs.end(), [](const RunSummary& r) { return r.collided; });
    if (collision == runs.end()) {
      outcome.critical_distance = margin;
      outcome.runs = std::move(runs);
      return outcome;
    }
    outcome.failures.push_back(*collision);
    outcome.runs = std::move(runs);  // the largest margin's runs stand when none is clear
  }
  return outcome;
}

VariantMeans means_of(const std::vector<RunSummary>& runs) {
  VariantMeans means;
  if (runs.empty()) return means;
  double distance = 0.0;
  double seconds = 0.0;
  for (const RunSummary& run : runs) {
    distance += run.reached_distance;
    seconds += run.reached_seconds;
    means.goals_reached += run.goals_reached;
    means.goals_refused += run.goals_refused;
    means.recovery_seconds += run.recovery_seconds;
    means.drove_off += run.drove_off ? 1 : 0;
  }
  const double n = static_cast<double>(runs.size());
  means.average_speed = seconds > 0.0 ? distance / seconds : 0.0;
  means.goals_reached /= n;
  means.goals_refused /= n;
  means.recovery_seconds /= n;
  return means;
}

}  // namespace rigdesign::scenarios
