#include "report/localize_report.hpp"

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
          {"probability", h.probability},
          {"side", h.side > 0   ? "left"
                   : h.side < 0 ? "right"
                                : "on the path"},
          {"rssi_at_1m_dbm", h.rssi_at_1m_dbm},
          {"rssi_at_1m_sd_db", h.level_sd_db},
          {"exponent", h.exponent},
          {"exponent_sd", h.exponent_sd},
          {"cost", h.cost}};
}

double region_area(const localize::PositionPosterior& region) {
  double cells = 0;
  for (const double v : region.log_density)
    if (v >= region.threshold) cells += 1;
  return cells * region.cell * region.cell;
}

std::string side_name(int side) {
  return side > 0 ? "left of the path" : side < 0 ? "right of the path" : "on the path";
}

// What the range fit used and found: scans, floor, noise, exponent.
void report_fit(const localize::EmitterEstimate& estimate, const LocalizeOptions& options,
                nlohmann::json* item, std::ostream& out) {
  const localize::ScanSeries& s = *estimate.scans;
  const localize::RangeFitResult& fit = estimate.fit;
  const int unheard = s.unheard_logged + s.unheard_interpolated;
  (*item)["scans"] = {{"heard", s.heard},
                      {"unheard_logged", s.unheard_logged},
                      {"unheard_interpolated", s.unheard_interpolated},
                      {"unheard_unplaced", s.unheard_unplaced},
                      {"floor_dbm", s.floor_dbm},
                      {"floor_source", to_string(s.floor_source)},
                      {"scan_period_s", s.scan_period_s}};
  (*item)["noise"] = {{"sigma_db", fit.sigma_db},
                      {"correlated_share", fit.correlated_share},
                      {"correlation_length_m", fit.correlation_length},
                      {"effective_share", fit.effective_share}};
  (*item)["exponent_identified"] = fit.exponent_identified;
  (*item)["ambiguous"] = estimate.ambiguous;
  (*item)["tie_break"] = estimate.tie_break;
  if (options.json) return;
  out << "  scans: " << s.heard << " heard, " << unheard << " below the floor "
      << fixed(s.floor_dbm, 1) << " dBm (" << to_string(s.floor_source) << ")";
  if (s.unheard_interpolated > 0)
    out << ", of which " << s.unheard_interpolated << " placed in straight gaps of the timeline";
  if (s.unheard_unplaced > 0)
    out << "; " << s.unheard_unplaced
        << " missed scans in gaps across bends left out (log them as lines with an empty rssi)";
  out << "; scan period " << model::format_number(s.scan_period_s, 3) << " s\n";
  out << "  noise: sigma " << fixed(fit.sigma_db, 1) << " dB per scan, "
      << fixed(100.0 * fit.correlated_share, 0) << " % of it correlated over "
      << fixed(fit.correlation_length, 2) << " m along the path: " << fixed(fit.effective_share, 3)
      << " independent samples per scan\n";
  if (!estimate.hypotheses.empty() && options.params.fit.exponent_prior > 0) {
    const localize::Hypothesis& h = estimate.hypotheses.front();
    out << "  exponent " << fixed(h.exponent, 2) << " +- " << fixed(h.exponent_sd, 2)
        << (fit.exponent_identified
                ? " (the path's spread of distances tells it)\n"
                : " (not identifiable on this path: its distances to the emitter hardly vary, so "
                  "the estimate rests on the prior " +
                      model::format_number(options.params.path_loss.exponent) + " +- " +
                      model::format_number(options.params.fit.exponent_prior) + ")\n");
  }
}

// The 95 % region and, for ambiguous hypotheses, why their order is not evidence.
void report_region(const localize::EmitterEstimate& estimate, const LocalizeOptions& options,
                   nlohmann::json* item, std::ostream& out) {
  if (estimate.region) {
    (*item)["region"] = {{"mass", estimate.region->credible_mass},
                         {"area_m2", region_area(*estimate.region)}};
  }
  if (options.json) return;
  if (estimate.ambiguous) {
    const auto& h = estimate.hypotheses;
    out << "  ambiguous: hypotheses 1 and 2 are indistinguishable (probabilities "
        << fixed(h[0].probability, 2) << " and " << fixed(h[1].probability, 2)
        << "; their fits are closer than a 95 % likelihood-ratio test can separate); "
        << (estimate.tie_break.empty()
                ? "their order is not evidence: --prefer-side left|right or --walls FILE can break "
                  "the tie"
                : "listed by " + estimate.tie_break)
        << '\n';
  }
  if (estimate.region) {
    out << "  " << fixed(100.0 * estimate.region->credible_mass, 0)
        << " % region: " << fixed(region_area(*estimate.region), 1)
        << " m^2 (highest posterior density)\n";
  }
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
                         {"hypotheses", nlohmann::json::array()}};
  for (const localize::Hypothesis& h : estimate.hypotheses)
    item["hypotheses"].push_back(to_json(h));
  if (!options.json) {
    out << "emitter " << estimate.bssid << " (" << to_string(method) << "): " << estimate.readings
        << " log lines";
    if (method == localize::LocalizeMethod::nls) {
      out << " (every scan, heard or not)\n";
    } else {
      out << ", " << estimate.used << " heard at or above "
          << model::format_number(options.params.path_loss.cutoff_dbm)
          << " dBm (paper 4's cut-off), " << estimate.chunks.size() << " chunks\n";
    }
    out << "  geometry: "
        << (g.dimensions == 3
                ? "3D"
                : "2D, z unobservable (height spread " + fixed(g.height_spread, 2) + " m)")
        << (g.collinear ? ", collinear (lateral spread " + fixed(g.lateral_spread, 2) +
                              " m): mirror image unresolved"
                        : "")
        << '\n';
  }
  if (estimate.scans) report_fit(estimate, options, &item, out);
  if (!options.json) {
    if (estimate.hypotheses.empty())
      out << "  no estimate: nothing heard, too few chunks or a singular system\n";
    const bool nls = method == localize::LocalizeMethod::nls;
    const int shown_dimensions = nls ? 2 : g.dimensions;  // the range fit is horizontal
    for (std::size_t i = 0; i < estimate.hypotheses.size(); ++i) {
      const localize::Hypothesis& h = estimate.hypotheses[i];
      out << "  " << (nls ? "hypothesis " + std::to_string(i + 1) : std::string("estimate"))
          << (nls ? " (p " + fixed(h.probability, 2) + ", " + side_name(h.side) + ")"
                  : std::string())
          << ' ' << xyz(h.position, shown_dimensions) << " m, sd x "
          << fixed(std::sqrt(h.covariance(0, 0)), 2) << " y "
          << fixed(std::sqrt(h.covariance(1, 1)), 2)
          << (shown_dimensions == 3 ? " z " + fixed(std::sqrt(h.covariance(2, 2)), 2)
                                    : std::string())
          << " m, a " << fixed(h.rssi_at_1m_dbm, 1)
          << (nls ? " +- " + fixed(h.level_sd_db, 1) : std::string()) << " dBm, n "
          << fixed(h.exponent, 2) << '\n';
    }
  }
  report_region(estimate, options, &item, out);
  if (truth) {
    const localize::EmitterKpis k =
        localize::evaluate_emitter(log, emitter, *truth, estimate, options.params, options.kpi);
    item["truth"] = to_json(*truth);
    item["kpis"] = {
        {"error_m", k.final_error},
        {"nearest_hypothesis_error_m", k.nearest_hypothesis_error},
        {"expected_error_m", k.expected_error},
        {"in_region", k.in_region},
        {"credible_level", k.credible_level ? nlohmann::json(*k.credible_level) : nlohmann::json()},
        {"running_smallest_m", k.running.smallest},
        {"running_mean_m", k.running.mean},
        {"running_rms_m", k.running.rms},
        {"detected", k.detected},
        {"heard_share", k.heard_share}};
    item["kpis"]["data_amount"] = k.data_amount ? nlohmann::json(*k.data_amount) : nlohmann::json();
    if (!options.json) {
      out << "  truth " << xyz(*truth, g.dimensions) << ": error " << fixed(k.final_error, 2)
          << " m (nearest hypothesis " << fixed(k.nearest_hypothesis_error, 2)
          << " m, probability-weighted " << fixed(k.expected_error, 2) << " m); "
          << (k.in_region ? "inside" : "outside") << " the stated 95 % region";
      if (k.running.count > 0) {
        out << "; running estimate smallest " << fixed(k.running.smallest, 2) << ", mean "
            << fixed(k.running.mean, 2) << ", RMS " << fixed(k.running.rms, 2) << " m; C = "
            << (k.data_amount ? std::to_string(*k.data_amount) + " readings" : std::string("never"))
            << " (within " << model::format_number(options.kpi.acceptable_error) << " m)";
      }
      out << "; " << (k.detected ? "detected" : "not detected") << '\n';
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
       {"runs", "mean m", "median m", "RMSE m", "expected mean", "nearest mean", "in 95 %",
        "C median", "C reached", "detected %", "ambiguous", "unsolved"}) {
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
                     fixed(row.final_error.rms, 2), fixed(row.expected_error.mean, 2),
                     fixed(row.nearest_error.mean, 2),
                     std::to_string(row.in_region) + "/" + std::to_string(row.runs),
                     fixed(row.median_data_amount, 0), std::to_string(row.reached),
                     fixed(100.0 * row.detection_share, 0), std::to_string(row.ambiguous_runs),
                     std::to_string(row.unsolved_runs)});
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
                                {"expected_mean_m", row.expected_error.mean},
                                {"in_region_runs", row.in_region},
                                {"multiple_hypothesis_runs", row.multiple_runs},
                                {"ambiguous_runs", row.ambiguous_runs},
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
      << model::format_number(options.scenario_params.tx_offset_db) << " dB; errors of the first "
      << "hypothesis (expected: probability-weighted over the hypotheses; nearest: of the one "
      << "nearest the truth); in 95 %: runs whose truth lies in the stated region; C in "
      << "readings to reach " << model::format_number(options.kpi.acceptable_error) << " m\n";
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
