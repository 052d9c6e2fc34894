#pragma once
// `rigdesign localize`'s options: what the command runs, and the settings its text report
// states beside the results (the cut-off, the priors, the acceptable error).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/gas_detection.hpp"
#include "rigdesign/localize/kpis.hpp"
#include "rigdesign/localize/log_generator.hpp"

namespace rigdesign::report {

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
  std::vector<double> search_area;  // --search-area X0 Y0 X1 Y1 [m], empty: not given
  std::string environment;          // --environment NAME: a published exponent preset
  std::string wls_weighting;        // --wls-weighting rows|residuals (empty: rows)
  bool calibrate = false;           // --calibrate: fit the path-loss model to --truth
  bool path_loss_given = false;     // --rssi-at-1m or --exponent on the command line
  std::string gas_truth;
  localize::LocalizeParams params;
  localize::ScenarioParams scenario_params;
  localize::KpiParams kpi;
  localize::GasDetectionParams gas;
  bool json = false;
  std::string out;
};

}  // namespace rigdesign::report
