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

// One run of `seed` at `margin` with `rig`'s mounts.
RunSummary run_one(const ScenarioFactory& make_scenario, const model::Rig& rig,
                   const model::SensorLibrary& library, const ScenarioParams& params,
                   std::uint64_t seed, double margin) {
  ScenarioParams run_params = params;
  run_params.seed = seed;
  run_params.clearance_margin = margin;
  const ScenarioDefinition scenario = make_scenario(seed, rig.body.radius);
  return summarize_run(seed, margin, run_scenario(scenario, rig, library, run_params));
}

// Every seed at `margin`, `threads` at a time; results and callbacks in seed order.
std::vector<RunSummary> run_all_seeds(const ScenarioFactory& make_scenario, const model::Rig& rig,
                                      const model::SensorLibrary& library,
                                      const ScenarioParams& params, double margin,
                                      const SweepSettings& settings,
                                      const std::function<void(const RunSummary&)>& on_run) {
  std::vector<RunSummary> runs(static_cast<std::size_t>(settings.seeds));
  const int threads = std::max(1, settings.threads);
  for (int start = 0; start < settings.seeds; start += threads) {
    const int batch = std::min(threads, settings.seeds - start);
    model::parallel_for(static_cast<std::size_t>(batch), batch, [&](std::size_t j) {
      const std::size_t s = static_cast<std::size_t>(start) + j;
      runs[s] = run_one(make_scenario, rig, library, params, settings.first_seed + s, margin);
    });
    for (int j = 0; j < batch; ++j)
      if (on_run) on_run(runs[static_cast<std::size_t>(start + j)]);
  }
  return runs;
}

}  // namespace

ScenarioParams params_for_subset(const model::Rig& subset, ScenarioParams params,
                                 bool& clearing_added) {
  clearing_added = false;
  const std::vector<costmap::ObservationSource> sources = mount_sources_of(subset, params);
  const bool clears = std::any_of(sources.begin(), sources.end(),
                                  [](const costmap::ObservationSource& s) { return s.clearing; });
  if (clears || sources.empty()) return params;
  clearing_added = true;
  for (std::size_t i = 0; i < subset.mounts.size(); ++i) {
    const std::string& id = subset.mounts[i].id;
    const auto named = std::find_if(params.mount_sources.begin(), params.mount_sources.end(),
                                    [&](const auto& n) { return n.name == id; });
    if (named != params.mount_sources.end()) {
      named->source.clearing = true;
    } else {
      costmap::ObservationSource own = sources[i];
      own.clearing = true;
      params.mount_sources.push_back({id, own});
    }
  }
  return params;
}

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
  const ScenarioParams own_params = params_for_subset(subset, params, outcome.clearing_added);
  try {
    check_scenario_inputs(subset, library, own_params);
  } catch (const model::InputError& error) {
    outcome.skipped = error.what();
    return outcome;
  }
  for (const double margin : settings.margins) {
    std::vector<RunSummary> runs =
        run_all_seeds(make_scenario, subset, library, own_params, margin, settings, on_run);
    outcome.runs_made += static_cast<int>(runs.size());
    std::vector<bool> collided;
    for (const RunSummary& run : runs) collided.push_back(run.collided);
    outcome.collided_by_margin.push_back(collided);
    const auto collision =
        std::find_if(runs.begin(), runs.end(), [](const RunSummary& r) { return r.collided; });
    if (collision == runs.end()) {
      outcome.critical_distance = margin;
      outcome.runs = std::move(runs);
      return outcome;
    }
    outcome.failures.push_back(*collision);  // the lowest seed that collided there
    outcome.runs = std::move(runs);          // the largest margin's runs stand when none is clear
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
