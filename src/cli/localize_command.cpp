// `rigdesign localize (--log FILE... | --scenario NAME [--seed S]) [--method wls|nls|map]`:
// radio-emitter localisation from RSSI logs and gas detection from CO2 logs (paper 4), with
// the KPIs against ground truth, a top-view plot, and `--seeds N --table` for the accuracy
// study across seeds (docs/localize.md).
#include <CLI/CLI.hpp>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "localize_calibration.hpp"
#include "number_checks.hpp"
#include "progress_line.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/logs/co2_log_reader.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"
#include "rigdesign/io/logs/log_kind.hpp"
#include "rigdesign/io/logs/rssi_csv.hpp"
#include "rigdesign/io/logs/walls_csv.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/localize/accuracy_table.hpp"
#include "rigdesign/localize/path_loss_calibration.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/render/localize_plot.hpp"
#include "rigdesign/render/localize_plot_content.hpp"
#include "rigdesign/report/localize_json.hpp"
#include "rigdesign/report/localize_options.hpp"
#include "rigdesign/report/localize_report.hpp"
#include "rigdesign/report/localize_text.hpp"

namespace rigdesign::cli {
namespace {

// The methods asked for: nls for one run, every method for --table, or --method.
std::vector<localize::LocalizeMethod> methods_of(const report::LocalizeOptions& options) {
  if (options.method.empty() && !options.table) return {localize::LocalizeMethod::nls};
  const auto method = localize::parse_localize_method(options.method);
  require_option(method.has_value() || options.method == "all" || options.method.empty(),
                 "--method", "unknown method '" + options.method + "'", "wls, nls, map (or all)");
  if (method) return {*method};
  return {localize::LocalizeMethod::wls, localize::LocalizeMethod::nls,
          localize::LocalizeMethod::map};
}

// The plot as PNG and SVG; returns the files.
std::vector<std::string> write_plots(const std::string& folder, const std::string& stem,
                                     const render::LocalizePlot& plot) {
  io::prepare_output_folder(folder, "--out");
  std::vector<std::string> written;
  for (const char* extension : {".png", ".svg"}) {
    const std::string file = folder + "/" + stem + extension;
    render::plot_localization(plot, file);
    written.push_back(file);
  }
  return written;
}

// The scenario's log, truth and walls as files `localize --log` and `--walls` read back.
void write_scenario_files(const localize::Scenario& scenario, const std::string& folder,
                          const std::string& stem) {
  io::prepare_output_folder(folder, "--out");
  io::write_file_atomically(folder + "/" + stem + "_rssi.csv", io::to_rssi_csv(scenario.log));
  io::write_file_atomically(folder + "/" + stem + "_truth.csv",
                            io::to_emitter_truth_csv(scenario.truth));
  io::write_file_atomically(folder + "/" + stem + "_walls.csv", io::to_walls_csv(scenario.walls));
}

// One emitter: estimate, uncertainty, degeneracy, and KPIs when the truth is known.
int run_scenario(const report::LocalizeOptions& options, std::ostream& out) {
  localize::ScenarioParams params = options.scenario_params;
  params.seed = options.seed;
  const localize::Scenario scenario = localize::make_scenario(options.scenario, params);
  report::ScenarioReport report{&scenario, options.seed, {}, {}};
  render::LocalizePlot plot =
      render::rssi_plot(scenario.log, "localize: scenario " + scenario.name + ", seed " +
                                          std::to_string(options.seed));
  render::add_walls(scenario.walls, plot);
  for (const localize::LocalizeMethod method : methods_of(options)) {
    report.emitters.push_back(report::locate_emitter(
        scenario.log, 0, method, scenario.truth.front().position, options.params, options.kpi));
    render::add_estimate_markers(report.emitters.back().estimate, report.emitters.back().truth,
                                 plot);
  }
  if (!options.json) report::print_scenario(report, options, out);
  if (!options.out.empty()) {
    const std::string stem = scenario.name + "_seed" + std::to_string(options.seed);
    write_scenario_files(scenario, options.out, stem);
    if (!options.json)
      out << "  wrote " << options.out + "/" + stem + "_rssi.csv, _truth.csv and _walls.csv\n";
    report.plots = write_plots(options.out, stem, plot);
    if (!options.json) report::print_written(report.plots, out);
  }
  if (options.json) out << report::to_json(report).dump(2) << '\n';
  return kOk;
}

// An RSSI log: every emitter by every method asked for, with the truth of those --truth names.
report::LogReport locate_in_log(const localize::RssiLog& log, const std::string& path,
                                const std::vector<localize::EmitterTruth>& truth,
                                const std::vector<localize::LocalizeMethod>& methods,
                                const report::LocalizeOptions& options,
                                render::LocalizePlot& plot) {
  report::LogReport report{path, log.readings.size(), log.emitters.size(), {}, std::nullopt};
  for (std::size_t e = 0; e < log.emitters.size(); ++e) {
    std::optional<model::Vec3> known;
    for (const localize::EmitterTruth& t : truth) {
      if (t.bssid == log.emitters[e]) known = t.position;
    }
    for (const localize::LocalizeMethod method : methods) {
      report.emitters.push_back(report::locate_emitter(log, static_cast<int>(e), method, known,
                                                       options.params, options.kpi));
      render::add_estimate_markers(report.emitters.back().estimate, known, plot);
    }
  }
  return report;
}

// A CO2 log: detections of both thresholds, scored against --gas-truth when given.
report::LogReport detect_in_log(const localize::Co2Log& log, const report::LocalizeOptions& options,
                                render::LocalizePlot& plot) {
  std::vector<localize::Artifact> artifacts;
  if (!options.gas_truth.empty()) artifacts = io::read_artifacts(options.gas_truth);
  report::LogReport report{log.source,
                           log.readings.size(),
                           0,
                           {},
                           report::detect_gas_sources(log, artifacts, options.gas)};
  for (const report::GasModeReport& mode : report.gas->modes) {
    if (mode.mode == localize::GasThreshold::relative)
      render::add_detection_markers(mode.detections, plot);
  }
  render::add_gas_artifact_markers(artifacts, plot);
  return report;
}

int run_logs(const report::LocalizeOptions& options, std::ostream& out) {
  std::vector<localize::EmitterTruth> truth;
  if (!options.truth.empty()) truth = io::read_emitter_truth(options.truth);
  const std::vector<localize::LocalizeMethod> methods = methods_of(options);
  report::LogsReport report;
  for (const std::string& path : options.logs) {
    const std::string text = io::read_log_text(path);
    const std::string title = "localize: " + std::filesystem::path(path).filename().string();
    render::LocalizePlot plot;
    if (io::log_kind_of(text, path) == io::LogKind::co2) {
      const localize::Co2Log log = io::parse_co2_log(text, path);
      plot = render::co2_plot(log, title);
      report.logs.push_back(detect_in_log(log, options, plot));
    } else {
      const localize::RssiLog log = io::parse_rssi_csv(text, path);
      plot = render::rssi_plot(log, title);
      report.logs.push_back(locate_in_log(log, path, truth, methods, options, plot));
    }
    if (!options.json) report::print_log(report.logs.back(), options, out);
    if (!options.out.empty()) {
      const std::vector<std::string> plots =
          write_plots(options.out, std::filesystem::path(path).stem().string(), plot);
      report.plots.insert(report.plots.end(), plots.begin(), plots.end());
      if (!options.json) report::print_written(plots, out);
    }
  }
  if (options.json) out << report::to_json(report).dump(2) << '\n';
  return kOk;
}

// The accuracy table over seeds (--table), every scenario for --scenario all.
int run_table(const report::LocalizeOptions& options, std::ostream& out, std::ostream& err) {
  require_option(options.seeds >= 1 && options.seeds <= 10000, "--seeds", "is out of range",
                 "1 to 10000");
  std::vector<std::string> scenarios = {options.scenario};
  if (options.scenario == "all") scenarios = localize::scenario_names();
  const std::vector<localize::LocalizeMethod> methods = methods_of(options);
  std::vector<localize::AccuracyRow> rows;
  ProgressLine progress(err, "localize: accuracy table", "runs");
  const double runs = static_cast<double>(scenarios.size()) * options.seeds;
  double done_before = 0.0;
  for (const std::string& scenario : scenarios) {
    const auto on_seed = [&](double seeds_done, double) {
      progress.update(done_before + seeds_done, runs);
    };
    const std::vector<localize::AccuracyRow> scenario_rows =
        localize::accuracy_table(scenario, options.seeds, options.scenario_params, methods,
                                 options.params, options.kpi, on_seed);
    rows.insert(rows.end(), scenario_rows.begin(), scenario_rows.end());
    done_before += options.seeds;
  }
  progress.clear();  // the table follows on standard output
  if (options.json) {
    out << report::accuracy_json(rows, options).dump(2) << '\n';
  } else {
    report::print_accuracy(rows, options, out);
  }
  return kOk;
}

int run_resolved(const report::LocalizeOptions& options, std::ostream& out, std::ostream& err);

// --wls-weighting: rows (default: eq. 12 read as weighted least squares), residuals (before
// issue 33) or paper (eq. 12 as printed, w on the right-hand side only).
localize::WlsWeighting wls_weighting_of(const std::string& name) {
  require_option(name.empty() || name == "rows" || name == "residuals" || name == "paper",
                 "--wls-weighting", "is '" + name + "'", "paper, rows or residuals");
  if (name == "residuals") return localize::WlsWeighting::squared_residuals;
  if (name == "paper") return localize::WlsWeighting::paper;
  return localize::WlsWeighting::rows;
}

int run_localize(const report::LocalizeOptions& options, std::ostream& out, std::ostream& err) {
  require_option(options.logs.empty() != options.scenario.empty(), "--log",
                 "give either --log FILE... or --scenario NAME",
                 "--log FILE... or --scenario NAME [--seed S]");
  require_option(options.params.path_loss.exponent > 0, "--exponent", "must be positive",
                 "a path-loss exponent, e.g. 2.5");
  if (!options.out.empty()) io::prepare_output_folder(options.out, "--out");
  report::LocalizeOptions resolved = options;
  require_option(options.prefer_side.empty() || options.prefer_side == "left" ||
                     options.prefer_side == "right",
                 "--prefer-side", "is '" + options.prefer_side + "'", "left or right");
  resolved.params.prefer_side = options.prefer_side == "left"    ? 1
                                : options.prefer_side == "right" ? -1
                                                                 : 0;
  if (!std::isnan(options.floor_dbm)) resolved.params.scans.floor_dbm = options.floor_dbm;
  if (!std::isnan(options.scan_period_s))
    resolved.params.scans.scan_period_s = options.scan_period_s;
  if (!options.walls.empty()) resolved.params.walls = io::read_walls_csv(options.walls);
  // The range fit lists first the hypothesis most likely within the acceptable error.
  resolved.params.fit.decision_radius = options.kpi.acceptable_error;
  resolved.params.chunking.weighting = wls_weighting_of(options.wls_weighting);
  if (!options.environment.empty()) {
    const localize::EnvironmentPreset* preset =
        localize::find_environment_preset(options.environment);
    std::string names;
    for (const localize::EnvironmentPreset& p : localize::environment_presets())
      names += (names.empty() ? "" : ", ") + p.name;
    require_option(preset != nullptr, "--environment", "is '" + options.environment + "'",
                   "one of " + names);
    resolved.params.path_loss.exponent = preset->exponent;
  }
  if (options.calibrate) return run_calibration(resolved, out);
  if (!options.search_area.empty()) {
    const std::vector<double>& area = options.search_area;
    // A site, not a continent: the posterior grid's cells grow with the area.
    constexpr double kLargestSide = 10000.0;  // [m]
    require_option(area[0] < area[2] && area[1] < area[3] && area[2] - area[0] <= kLargestSide &&
                       area[3] - area[1] <= kLargestSide,
                   "--search-area",
                   "is " + model::format_number(area[0]) + " " + model::format_number(area[1]) +
                       " " + model::format_number(area[2]) + " " + model::format_number(area[3]),
                   "X0 Y0 X1 Y1 [m] with X0 < X1, Y0 < Y1 and sides of at most 10 km");
    resolved.params.fit.search_area =
        std::array<model::Vec2, 2>{model::Vec2(area[0], area[1]), model::Vec2(area[2], area[3])};
  }
  return run_resolved(resolved, out, err);
}

int run_resolved(const report::LocalizeOptions& options, std::ostream& out, std::ostream& err) {
  if (!options.scenario.empty()) {
    if (options.scenario != "all")
      localize::make_scenario(options.scenario, {});  // unknown names fail here, exit 2
    if (options.table) return run_table(options, out, err);
    require_option(options.scenario != "all", "--scenario", "'all' needs --table",
                   "a scenario name");
    return run_scenario(options, out);
  }
  require_option(!options.table, "--table", "needs --scenario",
                 "--scenario NAME --seeds N --table");
  return run_logs(options, out);
}

// The path-loss model and the range fit's priors, floor, scan period and walls.
void add_range_fit_options(CLI::App* app, report::LocalizeOptions& options) {
  const auto given = [&options](const std::string&) { options.path_loss_given = true; };
  app->add_option("--rssi-at-1m", options.params.path_loss.rssi_at_1m_dbm,
                  "Assumed RSSI at 1 m [dBm] (default -45)")
      ->check(finite_in(-120, 30, "a level in [-120, 30] dBm"))
      ->each(given);
  CLI::Option* exponent = app->add_option("--exponent", options.params.path_loss.exponent,
                                          "Assumed path-loss exponent (default 2.5)")
                              ->check(finite_in(0.5, 10, "an exponent in [0.5, 10]"))
                              ->each(given);
  app->add_option("--environment", options.environment,
                  "The exponent of a kind of environment (paper 4, Table 4, its reference [49]; "
                  "midpoints of ranges): free-space, urban-area, indoor-los, indoor-general, "
                  "indoor-factories, indoor-through-floor, underground-station (the thesis's "
                  "2.2-3 at 2.4 GHz)")
      ->excludes(exponent);
  app->add_flag("--calibrate", options.calibrate,
                "Fit the level at 1 m and the exponent to the logs' readings of the emitters "
                "--truth places (censored maximum likelihood), and print them");
  app->add_option("--wls-weighting", options.wls_weighting,
                  "wls: paper 4's chunk weight sqrt(c)/r scales both sides of each equation "
                  "(rows, default: eq. 12 as weighted least squares), only its right-hand side "
                  "(paper: eq. 12 as printed, diag(w) a = B q) or, as before issue 33, its "
                  "squared residual (residuals)");
  app->add_option("--cutoff", options.params.path_loss.cutoff_dbm,
                  "wls, map: readings at or below this are dropped [dBm] (default -80: paper 4 "
                  "drops -80 dBm or worse)")
      ->check(finite_in(-150, 0, "a level in [-150, 0] dBm"));
  app->add_option("--level-prior", options.params.fit.level_prior_db,
                  "nls: prior sd of the 1 m level about --rssi-at-1m [dB]")
      ->capture_default_str()
      ->check(positive_up_to(100.0, "a sd in (0, 100] dB"));
  app->add_option("--exponent-prior", options.params.fit.exponent_prior,
                  "nls: prior sd of the exponent about --exponent (0: fixed)")
      ->capture_default_str()
      ->check(finite_in(0, 10, "0 or a sd in (0, 10]"));
  app->add_option("--path-prior", options.params.fit.path_prior_scale,
                  "nls: a prior on the position falling as exp(-sqrt(distance from the path) / M), "
                  "for comparison only: it assumes emitters lie near the path (0: off) [m]")
      ->capture_default_str()
      ->check(finite_in(0, 1000, "0 or a distance in (0, 1000] m"));
  CLI::Option* area =
      app->add_option("--search-area", options.search_area,
                      "nls: the rectangle X0 Y0 X1 Y1 [m, the log's frame] the emitter is searched "
                      "in: a uniform prior there, nothing outside (default: the explored area)")
          ->expected(4)
          ->check(finite_in(-1e8, 1e8, "coordinates in [-1e8, 1e8] m"));
  app->add_option("--search-margin", options.params.fit.search_margin,
                  "nls: without --search-area, the explored area is the path's bounding box "
                  "grown by this [m]")
      ->capture_default_str()
      ->check(finite_in(0, 1000, "a distance in [0, 1000] m"))
      ->excludes(area);
  app->add_flag("!--no-correlation", options.params.fit.correlated_shadowing,
                "nls: treat scans as independent (no tempering for correlated shadowing)");
  app->add_option("--floor", options.floor_dbm,
                  "Receiver floor [dBm]: unheard scans are below it (default: the log's "
                  "'# floor_dbm:', else its weakest reading)")
      ->check(finite_in(-200, 0, "a level in [-200, 0] dBm"));
  app->add_option("--scan-period", options.scan_period_s,
                  "Seconds between scans (default: the log's '# scan_period_s:', else its median "
                  "step)")
      ->check(positive_up_to(3600.0, "a period in (0, 3600] s"));
  app->add_option("--walls", options.walls,
                  "Wall map CSV (x1,y1,x2,y2,attenuation_db) the range fit models");
  app->add_option("--prefer-side", options.prefer_side,
                  "List ambiguous hypotheses on this side of the path first: left or right")
      ->check(
          [](const std::string& side) {
            return side == "left" || side == "right" ? std::string()
                                                     : "is '" + side + "' (expected left or right)";
          },
          "left or right");
}

// The KPIs, the synthetic scenarios' radio and the CO2 detection.
void add_kpi_scenario_and_gas_options(CLI::App* app, report::LocalizeOptions& options) {
  app->add_option("--checkpoints", options.kpi.checkpoints,
                  "Running-estimate checkpoints per log for the KPIs (0: final estimate only)")
      ->capture_default_str()
      ->check(finite_in(0, 1000, "0 to 1000 checkpoints"));
  app->add_option("--acceptable-error", options.kpi.acceptable_error,
                  "Error counted as a detection, for C [m] (default 5)")
      ->check(positive_up_to(1000.0, "a distance in (0, 1000] m"));
  app->add_option("--shadowing", options.scenario_params.shadowing_db,
                  "Scenario shadowing sigma [dB] (default 6)")
      ->check(finite_in(0, 30, "a sigma in [0, 30] dB"));
  app->add_option("--tx-offset", options.scenario_params.tx_offset_db,
                  "Scenario phone level minus the assumed one [dB]")
      ->check(finite_in(-60, 60, "an offset in [-60, 60] dB"));
  app->add_option("--wall-loss", options.scenario_params.wall_attenuation_db,
                  "Scenario loss per wall [dB] (default 8)")
      ->check(finite_in(0, 60, "a loss in [0, 60] dB"));
  app->add_option("--time-constant", options.gas.time_constant,
                  "CO2 sensor time constant for the lag correction [s] (default 20: the "
                  "SCD30's tau63, paper 4's sensor)")
      ->check(finite_in(0, 3600, "a time constant in [0, 3600] s"));
  app->add_option("--sample-period", options.gas.sample_period,
                  "Seconds per reading of an untimed CO2 log (default 1)")
      ->check(positive_up_to(3600.0, "a period in (0, 3600] s"));
  app->add_option("--threshold", options.gas.fixed_threshold_ppm,
                  "Fixed CO2 threshold [ppm] (default 1800)")
      ->check(positive_up_to(1e6, "a concentration in (0, 1e6] ppm"));
  app->add_option("--mad-factor", options.gas.mad_factor,
                  "k of the relative CO2 threshold median + k MAD (default 6)")
      ->check(positive_up_to(1000.0, "a factor in (0, 1000]"));
  app->add_option("--moving-average", options.gas.moving_average,
                  "CO2: average this many readings (trailing) before the threshold (default 1: "
                  "paper 4's ground robot detects on single readings; its 5-sample average is "
                  "for the UAVs, not its ground-robot method)")
      ->check(finite_in(1, 1000, "1 to 1000 readings"));
  app->add_flag("--refine-strongest", options.gas.refine_strongest,
                "CO2: report the strongest reading in a detection's 5 m area instead of the "
                "first over the threshold (the thesis's future work, not its method)");
}

}  // namespace

Command setup_localize(CLI::App& parent) {
  auto options = std::make_shared<report::LocalizeOptions>();
  CLI::App* app = parent.add_subcommand(
      "localize", "Locate Wi-Fi emitters from RSSI logs and gas sources from CO2 logs (paper 4)");
  app->add_option("--log", options->logs,
                  "RSSI CSV (t,x,y,z,bssid,rssi) or CO2 logs (t,x,y,z,co2_ppm or 'x y co2_ppm')");
  app->add_option("--scenario", options->scenario,
                  "Synthetic scenario: loop, corner, room, hallway (all with --table)");
  add_seed_option(*app, options->seed, "the synthetic scenario (default 1)");
  app->add_flag("--table", options->table, "Accuracy table over seeds 1..--seeds, every method");
  app->add_option("--seeds", options->seeds, "Seeds for --table (default 20)")
      ->check(finite_in(1, 10000, "1 to 10000 seeds"));
  app->add_option("--method", options->method,
                  "wls (paper 4), nls (range fit, default), map (object map), all");
  app->add_option("--truth", options->truth, "Emitter ground truth CSV (bssid,x,y,z) for the KPIs");
  app->add_option("--gas-truth", options->gas_truth,
                  "SubT ground-truth JSON (gt_*.json) to score gas detections");
  add_range_fit_options(app, *options);
  add_kpi_scenario_and_gas_options(app, *options);
  add_format_option(*app, options->json);
  app->add_option("--out", options->out,
                  "Write plots (PNG and SVG) and, for a scenario, its log and truth here");
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_localize(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
