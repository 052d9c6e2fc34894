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

std::string gas_detection_rule(const GasReport& report) {
  const bool thesis = report.moving_average <= 1 && !report.refine_strongest;
  std::string rule = report.moving_average <= 1
                         ? "first reading over the threshold"
                         : "first moving average of " + std::to_string(report.moving_average) +
                               " readings over the threshold";
  rule += ", one detection per 5 m";
  if (report.refine_strongest)
    rule += ", moved to the strongest in its area (the thesis's future work)";
  if (report.moving_average > 1) rule += "; the moving average is paper 4's for its UAVs";
  return rule + (thesis ? " (paper 4's ground robot)" : " (not the thesis's ground-robot method)");
}

GasReport detect_gas_sources(const localize::Co2Log& log,
                             const std::vector<localize::Artifact>& artifacts,
                             const localize::GasDetectionParams& params) {
  GasReport report{log.source,
                   log.readings.size(),
                   log.timed,
                   localize::detection_lag(log, params),
                   {},
                   params.moving_average,
                   params.refine_strongest};
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
