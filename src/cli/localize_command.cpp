// `rigdesign localize (--log FILE... | --scenario NAME [--seed S]) [--method wls|nls|map]`:
// radio-emitter localisation from RSSI logs and gas detection from CO2 logs (paper 4), with
// the KPIs against ground truth, a top-view plot, and `--seeds N --table` for the accuracy
// study across seeds (docs/localize.md).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/logs/co2_log_reader.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"
#include "rigdesign/io/logs/log_kind.hpp"
#include "rigdesign/io/logs/rssi_csv.hpp"
#include "rigdesign/localize/accuracy_table.hpp"
#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/gas_detection.hpp"
#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/render/localize_plot.hpp"
#include "text_table.hpp"

namespace rigdesign::cli {
namespace {

struct LocalizeOptions {
  std::vector<std::string> logs;
  std::string scenario;
  std::uint64_t seed = 1;
  int seeds = 20;
  bool table = false;
  std::string method;  // empty: nls for one run, every method for --table
  std::string truth;
  std::string gas_truth;
  localize::LocalizeParams params;
  localize::ScenarioParams scenario_params;
  localize::KpiParams kpi;
  localize::GasDetectionParams gas;
  bool json = false;
  std::string out;
};

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

void add_plot_markers(const localize::EmitterEstimate& estimate,
                      const std::optional<model::Vec3>& truth, render::LocalizePlot* plot) {
  for (std::size_t i = 0; i < estimate.hypotheses.size(); ++i) {
    const localize::Hypothesis& h = estimate.hypotheses[i];
    plot->markers.push_back(
        {h.position, h.covariance.topLeftCorner<2, 2>(),
         to_string(estimate.method) + (i == 0 ? "" : " twin"),
         i == 0 ? render::PlotMarkerKind::estimate : render::PlotMarkerKind::alternative});
  }
  const bool drawn =
      std::any_of(plot->markers.begin(), plot->markers.end(), [&](const render::PlotMarker& m) {
        return m.kind == render::PlotMarkerKind::truth && truth && m.position == *truth;
      });
  if (truth && !drawn)
    plot->markers.push_back(
        {*truth, Eigen::Matrix2d::Zero(), estimate.bssid, render::PlotMarkerKind::truth});
}

void write_plots(const std::string& folder, const std::string& stem,
                 const render::LocalizePlot& plot, nlohmann::json* report, std::ostream& out,
                 bool json) {
  std::filesystem::create_directories(folder);
  for (const char* extension : {".png", ".svg"}) {
    const std::string file = folder + "/" + stem + extension;
    render::plot_localization(plot, file);
    (*report)["plots"].push_back(file);
    if (!json) out << "  wrote " << file << '\n';
  }
}

// One emitter: estimate, uncertainty, degeneracy, and KPIs when the truth is known.
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
  if (plot) add_plot_markers(estimate, truth, plot);
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

int run_table(const LocalizeOptions& options, std::ostream& out) {
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
  for (const std::string& scenario : scenarios) {
    for (const localize::AccuracyRow& row :
         localize::accuracy_table(scenario, options.seeds, options.scenario_params, methods,
                                  options.params, options.kpi)) {
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
      if (plot && mode == localize::GasThreshold::relative) {
        plot->markers.push_back(
            {d.position, Eigen::Matrix2d::Zero(), "", render::PlotMarkerKind::detection});
        plot->markers.push_back(
            {d.lag_corrected, Eigen::Matrix2d::Zero(), "", render::PlotMarkerKind::lag_corrected});
      }
    }
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
  if (plot) {
    for (const localize::Artifact& a : artifacts) {
      if (a.type == "gas")
        plot->markers.push_back({a.position, Eigen::Matrix2d::Zero(), "gas " + std::to_string(a.id),
                                 render::PlotMarkerKind::artifact});
    }
  }
  return report;
}

int run_scenario(const LocalizeOptions& options, std::ostream& out) {
  localize::ScenarioParams params = options.scenario_params;
  params.seed = options.seed;
  const localize::Scenario scenario = localize::make_scenario(options.scenario, params);
  nlohmann::json report = {
      {"scenario", scenario.name},           {"seed", options.seed},
      {"description", scenario.description}, {"readings", scenario.log.readings.size()},
      {"emitters", nlohmann::json::array()}, {"plots", nlohmann::json::array()}};
  if (!options.json) {
    out << "scenario " << scenario.name << ", seed " << options.seed << ": " << scenario.description
        << "; " << scenario.log.readings.size() << " readings\n";
  }
  render::LocalizePlot plot;
  plot.title = "localize: scenario " + scenario.name + ", seed " + std::to_string(options.seed);
  plot.value_label = "RSSI [dBm]";
  for (const localize::RssiReading& r : scenario.log.readings) {
    plot.path.push_back(r.position);
    plot.values.push_back(r.rssi_dbm);
  }
  for (const localize::WallSegment& wall : scenario.walls) plot.walls.emplace_back(wall.a, wall.b);
  for (const localize::LocalizeMethod method : methods_of(options)) {
    report["emitters"].push_back(report_emitter(
        scenario.log, 0, method, scenario.truth.front().position, options, &plot, out));
  }
  if (!options.out.empty()) {
    const std::string stem = scenario.name + "_seed" + std::to_string(options.seed);
    std::filesystem::create_directories(options.out);
    io::write_file_atomically(options.out + "/" + stem + "_rssi.csv",
                              io::to_rssi_csv(scenario.log));
    io::write_file_atomically(options.out + "/" + stem + "_truth.csv",
                              io::to_emitter_truth_csv(scenario.truth));
    if (!options.json) out << "  wrote " << options.out + "/" + stem + "_rssi.csv and _truth.csv\n";
    write_plots(options.out, stem, plot, &report, out, options.json);
  }
  if (options.json) out << report.dump(2) << '\n';
  return kOk;
}

int run_logs(const LocalizeOptions& options, std::ostream& out) {
  std::vector<localize::EmitterTruth> truth;
  if (!options.truth.empty()) truth = io::read_emitter_truth(options.truth);
  const std::vector<localize::LocalizeMethod> methods = methods_of(options);
  nlohmann::json report = {{"logs", nlohmann::json::array()}, {"plots", nlohmann::json::array()}};
  for (const std::string& path : options.logs) {
    const std::string text = io::read_log_text(path);
    render::LocalizePlot plot;
    plot.title = "localize: " + std::filesystem::path(path).filename().string();
    nlohmann::json item;
    if (io::log_kind_of(text, path) == io::LogKind::co2) {
      const localize::Co2Log log = io::parse_co2_log(text, path);
      plot.value_label = "CO2 [ppm]";
      for (const localize::Co2Reading& r : log.readings) {
        plot.path.push_back(r.position);
        plot.values.push_back(r.ppm);
      }
      item = report_gas(log, options, &plot, out);
    } else {
      const localize::RssiLog log = io::parse_rssi_csv(text, path);
      plot.value_label = "RSSI [dBm]";
      item = {
          {"file", path}, {"readings", log.readings.size()}, {"emitters", nlohmann::json::array()}};
      for (const localize::RssiReading& r : log.readings) {
        plot.path.push_back(r.position);
        plot.values.push_back(r.rssi_dbm);
      }
      if (!options.json)
        out << path << ": " << log.readings.size() << " readings of " << log.emitters.size()
            << " emitter(s)\n";
      for (std::size_t e = 0; e < log.emitters.size(); ++e) {
        std::optional<model::Vec3> known;
        for (const localize::EmitterTruth& t : truth) {
          if (t.bssid == log.emitters[e]) known = t.position;
        }
        for (const localize::LocalizeMethod method : methods) {
          item["emitters"].push_back(
              report_emitter(log, static_cast<int>(e), method, known, options, &plot, out));
        }
      }
    }
    if (!options.out.empty())
      write_plots(options.out, std::filesystem::path(path).stem().string(), plot, &report, out,
                  options.json);
    report["logs"].push_back(item);
  }
  if (options.json) out << report.dump(2) << '\n';
  return kOk;
}

int run_localize(const LocalizeOptions& options, std::ostream& out) {
  require_option(options.logs.empty() != options.scenario.empty(), "--log",
                 "give either --log FILE... or --scenario NAME",
                 "--log FILE... or --scenario NAME [--seed S]");
  require_option(options.params.path_loss.exponent > 0, "--exponent", "must be positive",
                 "a path-loss exponent, e.g. 2.5");
  if (!options.scenario.empty()) {
    if (options.scenario != "all")
      localize::make_scenario(options.scenario, {});  // unknown names fail here, exit 2
    if (options.table) return run_table(options, out);
    require_option(options.scenario != "all", "--scenario", "'all' needs --table",
                   "a scenario name");
    return run_scenario(options, out);
  }
  require_option(!options.table, "--table", "needs --scenario",
                 "--scenario NAME --seeds N --table");
  return run_logs(options, out);
}

}  // namespace

Command setup_localize(CLI::App& parent) {
  auto options = std::make_shared<LocalizeOptions>();
  CLI::App* app = parent.add_subcommand(
      "localize", "Locate Wi-Fi emitters from RSSI logs and gas sources from CO2 logs (paper 4)");
  app->add_option("--log", options->logs,
                  "RSSI CSV (t,x,y,z,bssid,rssi) or CO2 logs (t,x,y,z,co2_ppm or 'x y co2_ppm')");
  app->add_option("--scenario", options->scenario,
                  "Synthetic scenario: loop, corner, room, hallway (all with --table)");
  app->add_option("--seed", options->seed, "Seed of the synthetic scenario (default 1)");
  app->add_flag("--table", options->table, "Accuracy table over seeds 1..--seeds, every method");
  app->add_option("--seeds", options->seeds, "Seeds for --table (default 20)");
  app->add_option("--method", options->method,
                  "wls (paper 4), nls (range fit, default), map (object map), all");
  app->add_option("--truth", options->truth, "Emitter ground truth CSV (bssid,x,y,z) for the KPIs");
  app->add_option("--gas-truth", options->gas_truth,
                  "SubT ground-truth JSON (gt_*.json) to score gas detections");
  app->add_option("--rssi-at-1m", options->params.path_loss.rssi_at_1m_dbm,
                  "Assumed RSSI at 1 m [dBm] (default -45)");
  app->add_option("--exponent", options->params.path_loss.exponent,
                  "Assumed path-loss exponent (default 2.5)");
  app->add_option("--cutoff", options->params.path_loss.cutoff_dbm,
                  "Drop readings below this [dBm] (default -80)");
  app->add_flag("--fit-exponent", options->params.fit.estimate_exponent,
                "nls also fits the path-loss exponent");
  app->add_option("--huber", options->params.fit.huber_db,
                  "nls Huber threshold [dB] (0: least squares)");
  app->add_option("--level-prior", options->params.fit.level_prior_db,
                  "nls prior sigma on the 1 m level [dB] (default 4; 0: none)");
  app->add_flag("--cutoff-model", options->params.fit.model_cutoff,
                "nls: model the cut-off as a truncation (experimental)");
  app->add_flag("!--no-correlation", options->params.fit.correlated_shadowing,
                "nls: treat chunks as independent (no effective-sample weighting)");
  app->add_option("--acceptable-error", options->kpi.acceptable_error,
                  "Error counted as a detection, for C [m] (default 5)");
  app->add_option("--shadowing", options->scenario_params.shadowing_db,
                  "Scenario shadowing sigma [dB] (default 6)");
  app->add_option("--tx-offset", options->scenario_params.tx_offset_db,
                  "Scenario phone level minus the assumed one [dB]");
  app->add_option("--wall-loss", options->scenario_params.wall_attenuation_db,
                  "Scenario loss per wall [dB] (default 8)");
  app->add_option("--time-constant", options->gas.time_constant,
                  "CO2 sensor time constant for the lag correction [s]");
  app->add_option("--sample-period", options->gas.sample_period,
                  "Seconds per reading of an untimed CO2 log (default 1)");
  app->add_option("--threshold", options->gas.fixed_threshold_ppm,
                  "Fixed CO2 threshold [ppm] (default 1800)");
  app->add_option("--mad-factor", options->gas.mad_factor,
                  "k of the relative CO2 threshold median + k MAD (default 6)");
  app->add_flag("--json", options->json, "Print JSON");
  app->add_option("--out", options->out,
                  "Write plots (PNG and SVG) and, for a scenario, its log and truth here");
  return {app, [options](std::ostream& out, std::ostream&) { return run_localize(*options, out); }};
}

}  // namespace rigdesign::cli
