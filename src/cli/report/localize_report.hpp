#pragma once
// The parts of `rigdesign localize`'s report: one emitter, one CO2 log, the accuracy table,
// each as text (to `out`) or JSON, with the plot's markers.
#include <nlohmann/json.hpp>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/gas_detection.hpp"
#include "rigdesign/localize/kpis.hpp"
#include "rigdesign/localize/log_generator.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/render/localize_plot.hpp"

namespace rigdesign::cli {

struct LocalizeOptions {
  std::vector<std::string> logs;
  std::string scenario;
  std::uint64_t seed = 1;
  int seeds = 20;
  bool table = false;
  std::string method;  // empty: nls for one run, every method for --table
  std::string truth;
  std::string walls;        // --walls FILE: a wall map the range fit models
  std::string prefer_side;  // --prefer-side left|right
  double floor_dbm = std::numeric_limits<double>::quiet_NaN();      // --floor, NaN: not given
  double scan_period_s = std::numeric_limits<double>::quiet_NaN();  // --scan-period
  std::string gas_truth;
  localize::LocalizeParams params;
  localize::ScenarioParams scenario_params;
  localize::KpiParams kpi;
  localize::GasDetectionParams gas;
  bool json = false;
  std::string out;
};

/// The methods asked for: nls for one run, every method for --table, or --method.
std::vector<localize::LocalizeMethod> methods_of(const LocalizeOptions& options);

/// One emitter: estimate, uncertainty, degeneracy, and KPIs when the truth is known; adds
/// its markers to `plot` when given.
nlohmann::json report_emitter(const localize::RssiLog& log, int emitter,
                              localize::LocalizeMethod method,
                              const std::optional<model::Vec3>& truth,
                              const LocalizeOptions& options, render::LocalizePlot* plot,
                              std::ostream& out);

/// Both detection thresholds on a CO2 log, scored against --gas-truth when given.
nlohmann::json report_gas(const localize::Co2Log& log, const LocalizeOptions& options,
                          render::LocalizePlot* plot, std::ostream& out);

/// The accuracy table over seeds (--table).
int run_table(const LocalizeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace rigdesign::cli
