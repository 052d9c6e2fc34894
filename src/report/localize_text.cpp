#include "rigdesign/report/localize_text.hpp"

#include <array>
#include <cmath>
#include <ostream>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

std::string xyz(const model::Vec3& p, int dimensions = 3) {
  std::string text = "(" + fixed(p.x(), 2) + ", " + fixed(p.y(), 2);
  if (dimensions == 3) text += ", " + fixed(p.z(), 2);
  return text + ")";
}

std::string side_name(int side) {
  return side > 0 ? "left of the path" : side < 0 ? "right of the path" : "on the path";
}

// How wls applied paper 4's chunk weight (--wls-weighting).
const char* weighting_note(localize::WlsWeighting weighting) {
  switch (weighting) {
    case localize::WlsWeighting::rows:
      return "; chunk weight sqrt(c)/r on both sides of each equation (eq. 12 as weighted least "
             "squares)";
    case localize::WlsWeighting::squared_residuals:
      return "; chunk weight sqrt(c)/r on each squared residual (--wls-weighting residuals)";
    case localize::WlsWeighting::paper:
      return "; chunk weight sqrt(c)/r on the right-hand side only (eq. 12 as printed, "
             "--wls-weighting paper)";
  }
  return "";
}

void print_emitter_head(const EmitterReport& report, const LocalizeOptions& options,
                        std::ostream& out) {
  const localize::EmitterEstimate& estimate = report.estimate;
  const localize::GeometryAnalysis& g = estimate.geometry;
  out << "emitter " << estimate.bssid << " (" << to_string(report.method)
      << "): " << estimate.readings << " log lines";
  if (report.method == localize::LocalizeMethod::nls) {
    out << " (every scan, heard or not)\n";
  } else {
    out << ", " << estimate.used << " heard above "
        << model::format_number(options.params.path_loss.cutoff_dbm) << " dBm (paper 4's cut-off), "
        << estimate.chunks.size() << " chunks\n";
    // Paper 4 calibrated level and exponent per environment: say where these came from.
    const localize::PathLossParams& model = options.params.path_loss;
    out << "  path loss: a " << model::format_number(model.rssi_at_1m_dbm) << " dBm, n "
        << model::format_number(model.exponent) << ", "
        << (!options.environment.empty() ? "n from --environment " + options.environment
            : options.path_loss_given
                ? std::string("as given")
                : std::string("assumed, not calibrated (--calibrate on a log of a phone at "
                              "a known place, or --environment NAME)"))
        << (report.method == localize::LocalizeMethod::wls
                ? weighting_note(options.params.chunking.weighting)
                : "")
        << '\n';
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

// What the range fit used and found: scans, floor, noise, exponent.
void print_fit(const localize::EmitterEstimate& estimate, const LocalizeOptions& options,
               std::ostream& out) {
  const localize::ScanSeries& s = *estimate.scans;
  const localize::RangeFitResult& fit = estimate.fit;
  out << "  scans: " << s.heard << " heard, " << s.unheard_logged + s.unheard_interpolated
      << " below the floor " << fixed(s.floor_dbm, 1) << " dBm (" << to_string(s.floor_source)
      << ")";
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
  const std::array<model::Vec2, 2>& area = fit.search_area;
  out << "  searched " << fixed(area[0].x(), 1) << " " << fixed(area[0].y(), 1) << " .. "
      << fixed(area[1].x(), 1) << " " << fixed(area[1].y(), 1) << " m"
      << (options.params.fit.search_area
              ? std::string(" (--search-area)")
              : " (the explored area: the path's box grown by " +
                    model::format_number(options.params.fit.search_margin) +
                    " m; --search-area to give yours)")
      << (options.params.fit.path_prior_scale > 0
              ? ", path prior " + model::format_number(options.params.fit.path_prior_scale) + " m"
              : std::string())
      << '\n';
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

void print_hypotheses(const EmitterReport& report, std::ostream& out) {
  const localize::EmitterEstimate& estimate = report.estimate;
  if (estimate.hypotheses.empty())
    out << "  no estimate: nothing heard, too few chunks or a singular system\n";
  const bool nls = report.method == localize::LocalizeMethod::nls;
  const int shown_dimensions = nls ? 2 : estimate.geometry.dimensions;  // the fit is horizontal
  for (std::size_t i = 0; i < estimate.hypotheses.size(); ++i) {
    const localize::Hypothesis& h = estimate.hypotheses[i];
    out << "  " << (nls ? "hypothesis " + std::to_string(i + 1) : std::string("estimate"))
        << (nls ? " (p " + fixed(h.probability, 2) + ", " + side_name(h.side) + ")" : std::string())
        << ' ' << xyz(h.position, shown_dimensions) << " m, sd x "
        << fixed(std::sqrt(h.covariance(0, 0)), 2) << " y "
        << fixed(std::sqrt(h.covariance(1, 1)), 2)
        << (shown_dimensions == 3 ? " z " + fixed(std::sqrt(h.covariance(2, 2)), 2) : std::string())
        << " m, a " << fixed(h.rssi_at_1m_dbm, 1)
        << (nls ? " +- " + fixed(h.level_sd_db, 1) : std::string()) << " dBm, n "
        << fixed(h.exponent, 2) << '\n';
  }
}

// The 95 % region and, for ambiguous hypotheses, why their order is not evidence.
void print_region(const EmitterReport& report, std::ostream& out) {
  const localize::EmitterEstimate& estimate = report.estimate;
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
        << " % region: " << fixed(report.region_area_m2, 1) << " m^2 (highest posterior density)\n";
  }
}

void print_truth(const EmitterReport& report, const LocalizeOptions& options, std::ostream& out) {
  const localize::EmitterKpis& k = *report.kpis;
  out << "  truth " << xyz(*report.truth, report.estimate.geometry.dimensions) << ": error "
      << fixed(k.final_error, 2) << " m (nearest hypothesis "
      << fixed(k.nearest_hypothesis_error, 2) << " m, probability-weighted "
      << fixed(k.expected_error, 2) << " m); " << (k.in_region ? "inside" : "outside")
      << " the stated 95 % region";
  if (k.running.count > 0) {
    out << "; running estimate smallest " << fixed(k.running.smallest, 2) << ", mean "
        << fixed(k.running.mean, 2) << ", RMS " << fixed(k.running.rms, 2) << " m; C = "
        << (k.data_amount ? std::to_string(*k.data_amount) + " readings" : std::string("never"))
        << " (within " << model::format_number(options.kpi.acceptable_error) << " m)";
  }
  out << "; " << (k.detected ? "detected" : "not detected") << '\n';
}

void print_emitter(const EmitterReport& report, const LocalizeOptions& options, std::ostream& out) {
  print_emitter_head(report, options, out);
  if (report.estimate.scans) print_fit(report.estimate, options, out);
  print_hypotheses(report, out);
  print_region(report, out);
  if (report.kpis) print_truth(report, options, out);
}

void print_score(const localize::GasScore& score, bool lagged, std::ostream& out) {
  out << "    " << (lagged ? "lag-corrected" : "as detected") << ": " << score.true_detections
      << " within 5 m of a gas artifact, " << score.false_detections << " not;";
  for (const localize::GasArtifactResult& a : score.artifacts) {
    out << " gas " << a.artifact.id << (a.found ? " found" : " missed") << " (path passes "
        << fixed(a.path_distance, 1) << " m, nearest detection "
        << (std::isfinite(a.nearest_detection) ? fixed(a.nearest_detection, 1) + " m" : "none")
        << ")";
  }
  out << '\n';
}

std::string threshold_name(localize::GasThreshold mode, const localize::GasDetectionParams& gas) {
  return mode == localize::GasThreshold::fixed
             ? "fixed " + model::format_number(gas.fixed_threshold_ppm) + " ppm"
             : "relative (median + " + model::format_number(gas.mad_factor) +
                   " MAD, >= " + model::format_number(gas.min_rise_ppm) + " ppm rise)";
}

void print_gas(const GasReport& report, const LocalizeOptions& options, std::ostream& out) {
  out << report.file << ": " << report.readings << " CO2 readings"
      << (report.timed ? ""
                       : " (untimed: " + model::format_number(options.gas.sample_period) +
                             " s per reading assumed)")
      << ", lag correction " << fixed(report.lag_s, 1) << " s\n";
  out << "  detection: " << gas_detection_rule(report) << '\n';
  for (const GasModeReport& mode : report.modes) {
    out << "  threshold " << threshold_name(mode.mode, options.gas) << ": "
        << mode.detections.size() << " detection(s)\n";
    for (const localize::GasDetection& d : mode.detections) {
      out << "    reading " << d.index << " at " << xyz(d.position, 2) << ": " << fixed(d.ppm, 0)
          << " ppm (threshold " << fixed(d.threshold_ppm, 0) << "), lag-corrected "
          << xyz(d.lag_corrected, 2) << '\n';
    }
    if (mode.as_detected) print_score(*mode.as_detected, false, out);
    if (mode.lag_corrected) print_score(*mode.lag_corrected, true, out);
  }
}

}  // namespace

void print_scenario(const ScenarioReport& report, const LocalizeOptions& options,
                    std::ostream& out) {
  const localize::Scenario& scenario = *report.scenario;
  out << "scenario " << scenario.name << ", seed " << report.seed << ": " << scenario.description
      << "; " << scenario.log.readings.size() << " readings\n";
  for (const EmitterReport& emitter : report.emitters) print_emitter(emitter, options, out);
}

void print_log(const LogReport& report, const LocalizeOptions& options, std::ostream& out) {
  if (report.gas) {
    print_gas(*report.gas, options, out);
    return;
  }
  out << report.file << ": " << report.readings << " readings of " << report.emitter_count
      << " emitter(s)\n";
  for (const EmitterReport& emitter : report.emitters) print_emitter(emitter, options, out);
}

void print_accuracy(const std::vector<localize::AccuracyRow>& rows, const LocalizeOptions& options,
                    std::ostream& out) {
  TextTable table;
  table.add_column("scenario", TextTable::Align::left);
  table.add_column("method", TextTable::Align::left);
  for (const char* header :
       {"runs", "mean m", "median m", "RMSE m", "expected mean", "nearest mean", "in 95 %",
        "C median", "C reached", "detected %", "ambiguous", "unsolved"}) {
    table.add_column(header, TextTable::Align::right);
  }
  for (const localize::AccuracyRow& row : rows) {
    table.add_row({row.scenario, to_string(row.method), std::to_string(row.runs),
                   fixed(row.final_error.mean, 2), fixed(row.final_error.median, 2),
                   fixed(row.final_error.rms, 2), fixed(row.expected_error.mean, 2),
                   fixed(row.nearest_error.mean, 2),
                   std::to_string(row.in_region) + "/" + std::to_string(row.runs),
                   fixed(row.median_data_amount, 0), std::to_string(row.reached),
                   fixed(100.0 * row.detection_share, 0), std::to_string(row.ambiguous_runs),
                   std::to_string(row.unsolved_runs)});
  }
  out << "accuracy over seeds 1.." << options.seeds << ", shadowing "
      << model::format_number(options.scenario_params.shadowing_db) << " dB, phone level offset "
      << model::format_number(options.scenario_params.tx_offset_db) << " dB; errors of the first "
      << "hypothesis (expected: probability-weighted over the hypotheses; nearest: of the one "
      << "nearest the truth); in 95 %: runs whose truth lies in the stated region; C in "
      << "readings to reach " << model::format_number(options.kpi.acceptable_error) << " m\n";
  table.print(out, "  ");
}

void print_written(const std::vector<std::string>& files, std::ostream& out) {
  for (const std::string& file : files) out << "  wrote " << file << '\n';
}

}  // namespace rigdesign::report
