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

// Every seed's own sweep: margins ascending until its first run without a collision (issue
// 54: the critical distance of a variant is the largest of these, and a confidence interval
// needs each seed's). Seeds run `threads` at a time; results and callbacks in seed order.
std::vector<std::vector<RunSummary>> sweep_each_seed(
    const ScenarioFactory& make_scenario, const model::Rig& rig,
    const model::SensorLibrary& library, const ScenarioParams& params,
    const SweepSettings& settings, const std::function<void(const RunSummary&)>& on_run) {
  std::vector<std::vector<RunSummary>> per_seed(static_cast<std::size_t>(settings.seeds));
  const int threads = std::max(1, settings.threads);
  for (int start = 0; start < settings.seeds; start += threads) {
    const int batch = std::min(threads, settings.seeds - start);
    model::parallel_for(static_cast<std::size_t>(batch), batch, [&](std::size_t j) {
      const std::size_t s = static_cast<std::size_t>(start) + j;
      const std::uint64_t seed = settings.first_seed + s;
      for (const double margin : settings.margins) {
        per_seed[s].push_back(run_one(make_scenario, rig, library, params, seed, margin));
        if (!per_seed[s].back().collided) break;
      }
    });
    for (int j = 0; j < batch; ++j)
      for (const RunSummary& run : per_seed[static_cast<std::size_t>(start + j)])
        if (on_run) on_run(run);
  }
  return per_seed;
}

// Every seed's run at `margin`: the one its own sweep made there, else a new run.
std::vector<RunSummary> runs_at(std::size_t margin_index,
                                const std::vector<std::vector<RunSummary>>& per_seed,
                                const ScenarioFactory& make_scenario, const model::Rig& rig,
                                const model::SensorLibrary& library, const ScenarioParams& params,
                                const SweepSettings& settings, int& runs_made,
                                const std::function<void(const RunSummary&)>& on_run) {
  std::vector<RunSummary> runs(per_seed.size());
  std::vector<std::size_t> missing;
  for (std::size_t s = 0; s < per_seed.size(); ++s) {
    if (per_seed[s].size() > margin_index) {
      runs[s] = per_seed[s][margin_index];
    } else {
      missing.push_back(s);
    }
  }
  const double margin = settings.margins[margin_index];
  model::parallel_for(missing.size(), std::max(1, settings.threads), [&](std::size_t k) {
    const std::size_t s = missing[k];
    runs[s] = run_one(make_scenario, rig, library, params, settings.first_seed + s, margin);
  });
  runs_made += static_cast<int>(missing.size());
  for (const std::size_t s : missing)
    if (on_run) on_run(runs[s]);
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
  const std::vector<std::vector<RunSummary>> per_seed =
      sweep_each_seed(make_scenario, subset, library, own_params, settings, on_run);
  std::size_t first_clear_everywhere = 0;  // the largest of the seeds' first clear margins
  for (const std::vector<RunSummary>& runs : per_seed) {
    outcome.runs_made += static_cast<int>(runs.size());
    const bool cleared = !runs.back().collided;
    outcome.seed_critical_distances.push_back(cleared ? std::optional<double>(runs.back().margin)
                                                      : std::nullopt);
    first_clear_everywhere = std::max(first_clear_everywhere, runs.size() - 1);
  }
  // Below it some seed collides; from it up, the first margin at which every seed's run is clear
  // (a seed clear at a smaller margin may still collide at a larger one).
  for (std::size_t m = 0; m < settings.margins.size(); ++m) {
    if (m < first_clear_everywhere) {
      for (const std::vector<RunSummary>& runs : per_seed) {
        if (runs.size() > m && runs[m].collided) {
          outcome.failures.push_back(runs[m]);  // the lowest seed that collided there
          break;
        }
      }
      continue;
    }
    std::vector<RunSummary> runs = runs_at(m, per_seed, make_scenario, subset, library, own_params,
                                           settings, outcome.runs_made, on_run);
    const auto collision =
        std::find_if(runs.begin(), runs.end(), [](const RunSummary& r) { return r.collided; });
    outcome.runs = std::move(runs);  // the largest margin's runs stand when none is clear
    if (collision == outcome.runs.end()) {
      outcome.critical_distance = settings.margins[m];
      return outcome;
    }
    outcome.failures.push_back(*collision);
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
