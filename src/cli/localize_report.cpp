#include "localize_report.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "progress_line.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"
#include "rigdesign/localize/accuracy_table.hpp"
#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/gas_detection.hpp"
#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/render/localize_plot.hpp"
#include "rigdesign/render/localize_plot_content.hpp"
#include "text_table.hpp"

namespace rigdesign::cli {
namespace {

std::string xyz(const model::Vec3& p, int dimensions = 3) {
  std::string text = "(" + fixed(p.x(), 2) + ", " + fixed(p.y(), 2);
  if (dimensions == 3) text += ", " + fixed(p.z(), 2);
  return text + ")";
}

nlohmann::json to_json(const model::Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

nlohmann::json to_json(const localize::Hypothesis& h) {
  nlohmann::json covariance = nlohmann::json::array();
  for (int r = 0; r < 3; ++r)
    covariance.push_back({h.covariance(r, 0), h.covariance(r, 1), h.covariance(r, 2)});
  return {{"position", to_json(h.position)},
          {"covariance", covariance},
          {"rssi_at_1m_dbm", h.rssi_at_1m_dbm},
          {"exponent", h.exponent},
          {"cost", h.cost}};
}

}  // namespace

nlohmann::json report_emitter(const localize::RssiLog& log, int emitter,
                              localize::LocalizeMethod method,
                              const std::optional<model::Vec3>& truth,
                              const LocalizeOptions& options, render::LocalizePlot* plot,
                              std::ostream& out) {
  const localize::EmitterEstimate estimate =
      localize::localize_emitter(log, emitter, method, options.params);
  const localize::GeometryAnalysis& g = estimate.geometry;
  nlohmann::json item = {{"bssid", estimate.bssid},
                         {"method", to_string(method)},
                         {"readings", estimate.readings},
                         {"used", estimate.used},
                         {"chunks", estimate.chunks.size()},
                         {"geometry",
                          {{"dimensions", g.dimensions},
                           {"z_observable", g.dimensions == 3},
                           {"collinear", g.collinear},
                           {"lateral_spread_m", g.lateral_spread},
                           {"height_spread_m", g.height_spread}}},
                         {"twin", estimate.twin},
                         {"hypotheses", nlohmann::json::array()}};
  for (const localize::Hypothesis& h : estimate.hypotheses)
    item["hypotheses"].push_back(to_json(h));
  if (method == localize::LocalizeMethod::nls) item["residual_sigma_db"] = estimate.sigma_db;
  if (!options.json) {
    out << "emitter " << estimate.bssid << " (" << to_string(method) << "): " << estimate.readings
        << " readings, " << estimate.used << " at or above "
        << model::format_number(options.params.path_loss.cutoff_dbm) << " dBm, "
        << estimate.chunks.size() << " chunks\n";
    out << "  geometry: "
        << (g.dimensions == 3
                ? "3D"
                : "2D, z unobservable (height spread " + fixed(g.height_spread, 2) + " m)")
        << (g.collinear ? ", collinear (lateral spread " + fixed(g.lateral_spread, 2) +
                              " m): mirror image unresolved"
                        : "")
        << '\n';
    if (estimate.hypotheses.empty()) out << "  no estimate: too few chunks or a singular system\n";
    for (std::size_t i = 0; i < estimate.hypotheses.size(); ++i) {
      const localize::Hypothesis& h = estimate.hypotheses[i];
      out << "  " << (i == 0 ? "estimate" : "twin    ") << ' ' << xyz(h.position, g.dimensions)
          << " m, sigma x " << fixed(std::sqrt(h.covariance(0, 0)), 2) << " y "
          << fixed(std::sqrt(h.covariance(1, 1)), 2)
          << (g.dimensions == 3 ? " z " + fixed(std::sqrt(h.covariance(2, 2)), 2) : std::string())
          << " m, a " << fixed(h.rssi_at_1m_dbm, 1) << " dBm, n " << fixed(h.exponent, 2) << '\n';
    }
  }
  if (truth) {
    const localize::EmitterKpis k =
        localize::evaluate_emitter(log, emitter, *truth, estimate, options.params, options.kpi);
    item["truth"] = to_json(*truth);
    item["kpis"] = {{"error_m", k.final_error},
                    {"nearest_hypothesis_error_m", k.nearest_hypothesis_error},
                    {"running_smallest_m", k.running.smallest},
                    {"running_mean_m", k.running.mean},
                    {"running_rms_m", k.running.rms},
                    {"detected", k.detected},
                    {"heard_share", k.heard_share}};
    item["kpis"]["data_amount"] = k.data_amount ? nlohmann::json(*k.data_amount) : nlohmann::json();
    if (!options.json) {
      out << "  truth " << xyz(*truth, g.dimensions) << ": error " << fixed(k.final_error, 2)
          << " m (nearest hypothesis " << fixed(k.nearest_hypothesis_error, 2)
          << " m); running estimate smallest " << fixed(k.running.smallest, 2) << ", mean "
          << fixed(k.running.mean, 2) << ", RMS " << fixed(k.running.rms, 2) << " m; C = "
          << (k.data_amount ? std::to_string(*k.data_amount) + " readings" : std::string("never"))
          << " (within " << model::format_number(options.kpi.acceptable_error) << " m); "
          << (k.detected ? "detected" : "not detected") << '\n';
    }
  }
  if (plot) render::add_estimate_markers(estimate, truth, *plot);
  return item;
}

std::vector<localize::LocalizeMethod> methods_of(const LocalizeOptions& options) {
  if (options.method.empty() && !options.table) return {localize::LocalizeMethod::nls};
  const auto method = localize::parse_localize_method(options.method);
  require_option(method.has_value() || options.method == "all" || options.method.empty(),
                 "--method", "unknown method '" + options.method + "'", "wls, nls, map (or all)");
  if (method) return {*method};
  return {localize::LocalizeMethod::wls, localize::LocalizeMethod::nls,
          localize::LocalizeMethod::map};
}

int run_table(const LocalizeOptions& options, std::ostream& out, std::ostream& err) {
  require_option(options.seeds >= 1 && options.seeds <= 10000, "--seeds", "is out of range",
                 "1 to 10000");
  std::vector<std::string> scenarios = {options.scenario};
  if (options.scenario == "all") scenarios = localize::scenario_names();
  const std::vector<localize::LocalizeMethod> methods = methods_of(options);
  TextTable table;
  table.add_column("scenario", TextTable::Align::left);
  table.add_column("method", TextTable::Align::left);
  for (const char* header :
       {"runs", "mean m", "median m", "RMSE m", "nearest mean", "nearest median", "C median",
        "C reached", "detected %", "twins", "unsolved"}) {
    table.add_column(header, TextTable::Align::right);
  }
  nlohmann::json report = {{"seeds", options.seeds},
                           {"shadowing_db", options.scenario_params.shadowing_db},
                           {"tx_offset_db", options.scenario_params.tx_offset_db},
                           {"rows", nlohmann::json::array()}};
  ProgressLine progress(err, "localize: accuracy table", "runs");
  const double runs = static_cast<double>(scenarios.size()) * options.seeds;
  double done_before = 0.0;
  for (const std::string& scenario : scenarios) {
    const auto on_seed = [&](double seeds_done, double) {
      progress.update(done_before + seeds_done, runs);
    };
    const std::vector<localize::AccuracyRow> rows =
        localize::accuracy_table(scenario, options.seeds, options.scenario_params, methods,
                                 options.params, options.kpi, on_seed);
    done_before += options.seeds;
    for (const localize::AccuracyRow& row : rows) {
      table.add_row({row.scenario, to_string(row.method), std::to_string(row.runs),
                     fixed(row.final_error.mean, 2), fixed(row.final_error.median, 2),
                     fixed(row.final_error.rms, 2), fixed(row.nearest_error.mean, 2),
                     fixed(row.nearest_error.median, 2), fixed(row.median_data_amount, 0),
                     std::to_string(row.reached), fixed(100.0 * row.detection_share, 0),
                     std::to_string(row.twin_runs), std::to_string(row.unsolved_runs)});
      report["rows"].push_back({{"scenario", row.scenario},
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
                                {"twin_runs", row.twin_runs},
                                {"unsolved_runs", row.unsolved_runs}});
    }
  }
  progress.clear();  // the table follows on standard output
  if (options.json) {
    out << report.dump(2) << '\n';
    return kOk;
  }
  out << "accuracy over seeds 1.." << options.seeds << ", shadowing "
      << model::format_number(options.scenario_params.shadowing_db) << " dB, phone level offset "
      << model::format_number(options.scenario_params.tx_offset_db) << " dB; errors of the best "
      << "hypothesis (nearest: of the hypothesis nearest the truth); C in readings to reach "
      << model::format_number(options.kpi.acceptable_error) << " m\n";
  table.print(out, "  ");
  return kOk;
}

nlohmann::json report_gas(const localize::Co2Log& log, const LocalizeOptions& options,
                          render::LocalizePlot* plot, std::ostream& out) {
  std::vector<localize::Artifact> artifacts;
  if (!options.gas_truth.empty()) artifacts = io::read_artifacts(options.gas_truth);
  nlohmann::json report = {{"file", log.source},
                           {"readings", log.readings.size()},
                           {"timed", log.timed},
                           {"lag_s", localize::detection_lag(log, options.gas)},
                           {"modes", nlohmann::json::array()}};
  if (!options.json) {
    out << log.source << ": " << log.readings.size() << " CO2 readings"
        << (log.timed ? ""
                      : " (untimed: " + model::format_number(options.gas.sample_period) +
                            " s per reading assumed)")
        << ", lag correction " << fixed(localize::detection_lag(log, options.gas), 1) << " s\n";
  }
  for (const localize::GasThreshold mode :
       {localize::GasThreshold::fixed, localize::GasThreshold::relative}) {
    const std::string name =
        mode == localize::GasThreshold::fixed
            ? "fixed " + model::format_number(options.gas.fixed_threshold_ppm) + " ppm"
            : "relative (median + " + model::format_number(options.gas.mad_factor) +
                  " MAD, >= " + model::format_number(options.gas.min_rise_ppm) + " ppm rise)";
    const std::vector<localize::GasDetection> detections =
        localize::detect_gas(log, mode, options.gas);
    nlohmann::json item = {
        {"threshold", mode == localize::GasThreshold::fixed ? "fixed" : "relative"},
        {"detections", nlohmann::json::array()}};
    if (!options.json)
      out << "  threshold " << name << ": " << detections.size() << " detection(s)\n";
    for (const localize::GasDetection& d : detections) {
      item["detections"].push_back({{"index", d.index},
                                    {"trigger_index", d.trigger_index},
                                    {"position", to_json(d.position)},
                                    {"lag_corrected", to_json(d.lag_corrected)},
                                    {"ppm", d.ppm},
                                    {"threshold_ppm", d.threshold_ppm}});
      if (!options.json) {
        out << "    reading " << d.index << " at " << xyz(d.position, 2) << ": " << fixed(d.ppm, 0)
            << " ppm (threshold " << fixed(d.threshold_ppm, 0) << "), lag-corrected "
            << xyz(d.lag_corrected, 2) << '\n';
      }
    }
    if (plot && mode == localize::GasThreshold::relative)
      render::add_detection_markers(detections, *plot);
    for (const bool lagged : {false, true}) {
      if (artifacts.empty()) break;
      const localize::GasScore score = localize::score_gas(log, detections, artifacts, lagged);
      nlohmann::json scored = {{"true_detections", score.true_detections},
                               {"false_detections", score.false_detections},
                               {"artifacts", nlohmann::json::array()}};
      if (!options.json) {
        out << "    " << (lagged ? "lag-corrected" : "as detected") << ": " << score.true_detections
            << " within 5 m of a gas artifact, " << score.false_detections << " not;";
      }
      for (const localize::GasArtifactResult& a : score.artifacts) {
        scored["artifacts"].push_back(
            {{"id", a.artifact.id},
             {"position", to_json(a.artifact.position)},
             {"path_distance_m", a.path_distance},
             {"nearest_detection_m", std::isfinite(a.nearest_detection)
                                         ? nlohmann::json(a.nearest_detection)
                                         : nlohmann::json()},
             {"found", a.found}});
        if (!options.json) {
          out << " gas " << a.artifact.id << (a.found ? " found" : " missed") << " (path passes "
              << fixed(a.path_distance, 1) << " m, nearest detection "
              << (std::isfinite(a.nearest_detection) ? fixed(a.nearest_detection, 1) + " m"
                                                     : "none")
              << ")";
        }
      }
      if (!options.json) out << '\n';
      item[lagged ? "score_lag_corrected" : "score"] = scored;
    }
    report["modes"].push_back(item);
  }
  if (plot) render::add_gas_artifact_markers(artifacts, *plot);
  return report;
}

}  // namespace rigdesign::cli
