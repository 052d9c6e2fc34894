#include "rigdesign/report/localize_report.hpp"

namespace rigdesign::report {
namespace {

// The area of the posterior grid cells inside its highest-density region [m^2].
double region_area(const localize::PositionPosterior& region) {
  double cells = 0;
  for (const double v : region.log_density)
    if (v >= region.threshold) cells += 1;
  return cells * region.cell * region.cell;
}

}  // namespace

EmitterReport locate_emitter(const localize::RssiLog& log, int emitter,
                             localize::LocalizeMethod method,
                             const std::optional<model::Vec3>& truth,
                             const localize::LocalizeParams& params,
                             const localize::KpiParams& kpi) {
  EmitterReport report;
  report.method = method;
  report.estimate = localize::localize_emitter(log, emitter, method, params);
  if (report.estimate.region) report.region_area_m2 = region_area(*report.estimate.region);
  report.truth = truth;
  if (truth)
    report.kpis = localize::evaluate_emitter(log, emitter, *truth, report.estimate, params, kpi);
  return report;
}

GasReport detect_gas_sources(const localize::Co2Log& log,
                             const std::vector<localize::Artifact>& artifacts,
                             const localize::GasDetectionParams& params) {
  GasReport report{
      log.source, log.readings.size(), log.timed, localize::detection_lag(log, params), {}};
  for (const localize::GasThreshold mode :
       {localize::GasThreshold::fixed, localize::GasThreshold::relative}) {
    GasModeReport item;
    item.mode = mode;
    item.detections = localize::detect_gas(log, mode, params);
    if (!artifacts.empty()) {
      item.as_detected = localize::score_gas(log, item.detections, artifacts, false);
      item.lag_corrected = localize::score_gas(log, item.detections, artifacts, true);
    }
    report.modes.push_back(std::move(item));
  }
  return report;
}

}  // namespace rigdesign::report
