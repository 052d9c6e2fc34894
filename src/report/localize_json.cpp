#include "rigdesign/report/localize_json.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace rigdesign::report {
namespace {

using nlohmann::json;

json position_json(const model::Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

json hypothesis_json(const localize::Hypothesis& h) {
  json covariance = json::array();
  for (int r = 0; r < 3; ++r)
    covariance.push_back({h.covariance(r, 0), h.covariance(r, 1), h.covariance(r, 2)});
  return {{"position", position_json(h.position)},
          {"covariance", covariance},
          {"probability", h.probability},
          {"probability_nearby", h.probability_nearby ? json(*h.probability_nearby) : json()},
          {"side", h.side > 0   ? "left"
                   : h.side < 0 ? "right"
                                : "on the path"},
          {"rssi_at_1m_dbm", h.rssi_at_1m_dbm},
          {"rssi_at_1m_sd_db", h.level_sd_db},
          {"exponent", h.exponent},
          {"exponent_sd", h.exponent_sd},
          {"cost", h.cost}};
}

// What the range fit used and found: scans, floor, noise, exponent.
void add_fit(const localize::EmitterEstimate& estimate, json& item) {
  const localize::ScanSeries& s = *estimate.scans;
  const localize::RangeFitResult& fit = estimate.fit;
  item["scans"] = {{"heard", s.heard},
                   {"unheard_logged", s.unheard_logged},
                   {"unheard_interpolated", s.unheard_interpolated},
                   {"unheard_unplaced", s.unheard_unplaced},
                   {"floor_dbm", s.floor_dbm},
                   {"floor_source", to_string(s.floor_source)},
                   {"scan_period_s", s.scan_period_s}};
  item["noise"] = {{"sigma_db", fit.sigma_db},
                   {"correlated_share", fit.correlated_share},
                   {"correlation_length_m", fit.correlation_length},
                   {"effective_share", fit.effective_share}};
  item["exponent_identified"] = fit.exponent_identified;
  item["search_area_m"] = {fit.search_area[0].x(), fit.search_area[0].y(), fit.search_area[1].x(),
                           fit.search_area[1].y()};
  item["ambiguous"] = estimate.ambiguous;
  item["tie_break"] = estimate.tie_break;
}

json kpis_json(const localize::EmitterKpis& k) {
  json kpis = {{"error_m", k.final_error},
               {"nearest_hypothesis_error_m", k.nearest_hypothesis_error},
               {"expected_error_m", k.expected_error},
               {"in_region", k.in_region},
               {"credible_level", k.credible_level ? json(*k.credible_level) : json()},
               {"running_smallest_m", k.running.smallest},
               {"running_mean_m", k.running.mean},
               {"running_rms_m", k.running.rms},
               {"detected", k.detected},
               {"heard_share", k.heard_share}};
  kpis["data_amount"] = k.data_amount ? json(*k.data_amount) : json();
  return kpis;
}

json score_json(const localize::GasScore& score) {
  json scored = {{"true_detections", score.true_detections},
                 {"false_detections", score.false_detections},
                 {"artifacts", json::array()}};
  for (const localize::GasArtifactResult& a : score.artifacts) {
    scored["artifacts"].push_back(
        {{"id", a.artifact.id},
         {"position", position_json(a.artifact.position)},
         {"path_distance_m", a.path_distance},
         {"nearest_detection_m",
          std::isfinite(a.nearest_detection) ? json(a.nearest_detection) : json()},
         {"found", a.found}});
  }
  return scored;
}

json gas_mode_json(const GasModeReport& mode) {
  json item = {{"threshold", mode.mode == localize::GasThreshold::fixed ? "fixed" : "relative"},
               {"detections", json::array()}};
  for (const localize::GasDetection& d : mode.detections) {
    item["detections"].push_back({{"index", d.index},
                                  {"trigger_index", d.trigger_index},
                                  {"position", position_json(d.position)},
                                  {"lag_corrected", position_json(d.lag_corrected)},
                                  {"ppm", d.ppm},
                                  {"threshold_ppm", d.threshold_ppm}});
  }
  if (mode.as_detected) item["score"] = score_json(*mode.as_detected);
  if (mode.lag_corrected) item["score_lag_corrected"] = score_json(*mode.lag_corrected);
  return item;
}

json emitters_json(const std::vector<EmitterReport>& emitters) {
  json list = json::array();
  for (const EmitterReport& emitter : emitters) list.push_back(to_json(emitter));
  return list;
}

}  // namespace

json to_json(const EmitterReport& report) {
  const localize::EmitterEstimate& estimate = report.estimate;
  const localize::GeometryAnalysis& g = estimate.geometry;
  json item = {{"bssid", estimate.bssid},
               {"method", to_string(report.method)},
               {"readings", estimate.readings},
               {"used", estimate.used},
               {"chunks", estimate.chunks.size()},
               {"geometry",
                {{"dimensions", g.dimensions},
                 {"z_observable", g.dimensions == 3},
                 {"collinear", g.collinear},
                 {"lateral_spread_m", g.lateral_spread},
                 {"height_spread_m", g.height_spread}}},
               {"hypotheses", json::array()}};
  for (const localize::Hypothesis& h : estimate.hypotheses)
    item["hypotheses"].push_back(hypothesis_json(h));
  if (estimate.scans) add_fit(estimate, item);
  if (estimate.region) {
    item["region"] = {{"mass", estimate.region->credible_mass}, {"area_m2", report.region_area_m2}};
  }
  if (report.truth) item["truth"] = position_json(*report.truth);
  if (report.kpis) item["kpis"] = kpis_json(*report.kpis);
  return item;
}

json to_json(const GasReport& report) {
  json modes = json::array();
  for (const GasModeReport& mode : report.modes) modes.push_back(gas_mode_json(mode));
  return {{"file", report.file},
          {"readings", report.readings},
          {"timed", report.timed},
          {"lag_s", report.lag_s},
          {"detection",
           {{"moving_average", report.moving_average},
            {"refine_strongest", report.refine_strongest},
            {"rule", gas_detection_rule(report)}}},
          {"modes", modes}};
}

json to_json(const ScenarioReport& report) {
  const localize::Scenario& scenario = *report.scenario;
  return {{"scenario", scenario.name},
          {"seed", report.seed},
          {"description", scenario.description},
          {"readings", scenario.log.readings.size()},
          {"emitters", emitters_json(report.emitters)},
          {"plots", report.plots}};
}

json to_json(const LogsReport& report) {
  json logs = json::array();
  for (const LogReport& log : report.logs) {
    logs.push_back(log.gas ? to_json(*log.gas)
                           : json{{"file", log.file},
                                  {"readings", log.readings},
                                  {"emitters", emitters_json(log.emitters)}});
  }
  return {{"logs", logs}, {"plots", report.plots}};
}

json accuracy_json(const std::vector<localize::AccuracyRow>& rows, const LocalizeOptions& options) {
  json list = json::array();
  for (const localize::AccuracyRow& row : rows) {
    list.push_back({{"scenario", row.scenario},
                    {"method", to_string(row.method)},
                    {"runs", row.runs},
                    {"mean_m", row.final_error.mean},
                    {"median_m", row.final_error.median},
                    {"rmse_m", row.final_error.rms},
                    {"nearest_mean_m", row.nearest_error.mean},
                    {"nearest_median_m", row.nearest_error.median},
                    {"data_amount_median", row.median_data_amount},
                    {"data_amount_reached", row.reached},
                    {"detection_share", row.detection_share},
                    {"expected_mean_m", row.expected_error.mean},
                    {"in_region_runs", row.in_region},
                    {"multiple_hypothesis_runs", row.multiple_runs},
                    {"ambiguous_runs", row.ambiguous_runs},
                    {"unsolved_runs", row.unsolved_runs}});
  }
  return {{"seeds", options.seeds},
          {"shadowing_db", options.scenario_params.shadowing_db},
          {"tx_offset_db", options.scenario_params.tx_offset_db},
          {"rows", list}};
}

}  // namespace rigdesign::report
