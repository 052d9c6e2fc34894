#pragma once
// What `rigdesign localize` reports, as data: per emitter and method the estimate with its
// KPIs, per CO2 log the detections of both thresholds with their scores, and the runs on a
// scenario or on log files that hold them. localize_text and localize_json render it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/gas_detection.hpp"
#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/localize/kpis.hpp"
#include "rigdesign/localize/log_generator.hpp"
#include "rigdesign/localize/rssi_log.hpp"

namespace rigdesign::report {

/// One emitter located by one method.
struct EmitterReport {
  localize::LocalizeMethod method = localize::LocalizeMethod::nls;
  localize::EmitterEstimate estimate;
  double region_area_m2 = 0.0;  ///< of the estimate's credible region, when it states one
  std::optional<model::Vec3> truth;
  std::optional<localize::EmitterKpis> kpis;  ///< when the truth is known
};

/// One detection threshold on a CO2 log.
struct GasModeReport {
  localize::GasThreshold mode = localize::GasThreshold::fixed;
  std::vector<localize::GasDetection> detections;
  /// Scored against the gas artifacts as detected and lag-corrected; none without artifacts.
  std::optional<localize::GasScore> as_detected;
  std::optional<localize::GasScore> lag_corrected;
};

/// A CO2 log under both thresholds.
struct GasReport {
  std::string file;
  std::size_t readings = 0;
  bool timed = true;                 ///< false: an untimed trace, a sample period assumed
  double lag_s = 0.0;                ///< the sensor's delay the lag correction undoes [s]
  std::vector<GasModeReport> modes;  ///< fixed, then relative
  int moving_average = 1;            ///< readings averaged (1: paper 4's ground robot)
  bool refine_strongest = false;     ///< strongest reading in the area (the thesis's future work)
};

/// How the detections were made, in words: paper 4's ground-robot rule (the first reading over
/// the threshold, one detection per 5 m) or which options depart from it.
std::string gas_detection_rule(const GasReport& report);

/// One --log file: an RSSI log with its emitters, or a CO2 log.
struct LogReport {
  std::string file;
  std::size_t readings = 0;
  std::size_t emitter_count = 0;
  std::vector<EmitterReport> emitters;  ///< per emitter, per method (RSSI)
  std::optional<GasReport> gas;         ///< a CO2 log
};

struct LogsReport {
  std::vector<LogReport> logs;
  std::vector<std::string> plots;  ///< written
};

/// A run on a synthetic scenario.
struct ScenarioReport {
  const localize::Scenario* scenario = nullptr;
  std::uint64_t seed = 1;
  std::vector<EmitterReport> emitters;  ///< per method
  std::vector<std::string> plots;       ///< written
};

/// Emitter `emitter` of `log` located by `method`; KPIs when `truth` is given.
EmitterReport locate_emitter(const localize::RssiLog& log, int emitter,
                             localize::LocalizeMethod method,
                             const std::optional<model::Vec3>& truth,
                             const localize::LocalizeParams& params,
                             const localize::KpiParams& kpi);

/// Both detection thresholds on `log`, scored against the gas ones of `artifacts`, if any.
GasReport detect_gas_sources(const localize::Co2Log& log,
                             const std::vector<localize::Artifact>& artifacts,
                             const localize::GasDetectionParams& params);

}  // namespace rigdesign::report
