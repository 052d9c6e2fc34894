#pragma once
/// The accuracy study: each method on one synthetic scenario across seeds 1..N, summarised
/// as paper 4's KPIs (what `rigdesign localize --scenario NAME --seeds N --table` prints).
#include <string>
#include <vector>

#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/kpis.hpp"
#include "rigdesign/localize/log_generator.hpp"
#include "rigdesign/model/progress.hpp"

namespace rigdesign::localize {

struct AccuracyRow {
  std::string scenario;
  LocalizeMethod method = LocalizeMethod::nls;
  int runs = 0;
  ErrorStats final_error;           ///< of the best hypothesis, across runs [m]
  ErrorStats nearest_error;         ///< of the hypothesis nearest the truth, across runs [m]
  ErrorStats expected_error;        ///< probability-weighted over the hypotheses [m]
  int in_region = 0;                ///< runs whose truth lies in the stated 95 % region
  double median_data_amount = 0.0;  ///< C over the runs that reached the acceptable error
  int reached = 0;                  ///< runs whose running estimate ever got within it
  double detection_share = 0.0;     ///< runs whose final estimate is within it
  int multiple_runs = 0;            ///< runs reporting more than one hypothesis
  int ambiguous_runs = 0;           ///< runs whose first two hypotheses are indistinguishable
  int unsolved_runs = 0;            ///< runs without an estimate (not in the error statistics)
};

/// One row per method, seeds 1..`seeds` (the params' seed is replaced). `progress` hears
/// (seeds done, seeds) after each seed.
std::vector<AccuracyRow> accuracy_table(const std::string& scenario, int seeds,
                                        ScenarioParams scenario_params,
                                        const std::vector<LocalizeMethod>& methods,
                                        const LocalizeParams& params = {},
                                        const KpiParams& kpi = {},
                                        const model::ProgressCallback& progress = {});

}  // namespace rigdesign::localize
