#include "rigdesign/localize/accuracy_table.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::localize {

std::vector<AccuracyRow> accuracy_table(const std::string& scenario, int seeds,
                                        ScenarioParams scenario_params,
                                        const std::vector<LocalizeMethod>& methods,
                                        const LocalizeParams& params, const KpiParams& kpi,
                                        const model::ProgressCallback& progress) {
  struct Collected {
    std::vector<double> final_errors, nearest_errors, expected_errors, amounts;
    int detected = 0, multiple = 0, ambiguous = 0, unsolved = 0, in_region = 0;
  };
  std::vector<Collected> collected(methods.size());
  for (int seed = 1; seed <= seeds; ++seed) {
    scenario_params.seed = static_cast<std::uint64_t>(seed);
    const Scenario generated = make_scenario(scenario, scenario_params);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const EmitterEstimate estimate = localize_emitter(generated.log, 0, methods[m], params);
      const EmitterKpis kpis = evaluate_emitter(generated.log, 0, generated.truth.front().position,
                                                estimate, params, kpi);
      Collected& c = collected[m];
      if (estimate.hypotheses.empty()) {
        ++c.unsolved;
      } else {
        c.final_errors.push_back(kpis.final_error);
        c.nearest_errors.push_back(kpis.nearest_hypothesis_error);
        c.expected_errors.push_back(kpis.expected_error);
      }
      c.in_region += kpis.in_region ? 1 : 0;
      c.ambiguous += estimate.ambiguous ? 1 : 0;
      if (kpis.data_amount) c.amounts.push_back(*kpis.data_amount);
      c.detected += kpis.detected ? 1 : 0;
      c.multiple += estimate.hypotheses.size() > 1 ? 1 : 0;
    }
    if (progress) progress(seed, seeds);
  }
  std::vector<AccuracyRow> rows;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const Collected& c = collected[m];
    AccuracyRow row;
    row.scenario = scenario;
    row.method = methods[m];
    row.runs = seeds;
    row.final_error = error_stats(c.final_errors);
    row.nearest_error = error_stats(c.nearest_errors);
    row.expected_error = error_stats(c.expected_errors);
    row.in_region = c.in_region;
    row.median_data_amount = error_stats(c.amounts).median;
    row.reached = static_cast<int>(c.amounts.size());
    row.detection_share = seeds > 0 ? static_cast<double>(c.detected) / seeds : 0.0;
    row.multiple_runs = c.multiple;
    row.ambiguous_runs = c.ambiguous;
    row.unsolved_runs = c.unsolved;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace rigdesign::localize
