#include "localize_calibration.hpp"

#include <nlohmann/json.hpp>

#include "app.hpp"
#include "command.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"
#include "rigdesign/io/logs/log_kind.hpp"
#include "rigdesign/io/logs/rssi_csv.hpp"
#include "rigdesign/localize/path_loss_calibration.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::cli {
namespace {

// One log's emitter and its fit; once refuse_unusable_fits has passed the rows, every row holds
// a usable fit (the two writers below print only such rows).
struct CalibrationRow {
  std::string log, bssid;
  std::optional<localize::PathLossCalibration> fit;
};

void print_rows(const std::vector<CalibrationRow>& rows, std::ostream& out) {
  using model::format_number;
  out << "path-loss calibration (rssi = a - 10 n log10 d + e, maximum likelihood over every scan "
         "at least "
      << format_number(localize::kCalibrationMinDistance)
      << " m from the emitter; unheard scans lie below the floor; the --walls map's losses taken "
         "off)\n";
  for (const CalibrationRow& row : rows) {
    out << "  " << row.log << " " << row.bssid << ": ";
    const localize::PathLossCalibration& c = *row.fit;
    out << "a " << format_number(c.rssi_at_1m_dbm, 3) << " +- " << format_number(c.level_sd_db, 2)
        << " dBm, n " << format_number(c.exponent, 3) << " +- " << format_number(c.exponent_sd, 2)
        << ", sigma " << format_number(c.sigma_db, 2) << " dB; " << c.heard << " heard and "
        << c.unheard << " unheard scans at " << format_number(c.nearest_m, 3) << "-"
        << format_number(c.farthest_m, 3) << " m\n    use: --rssi-at-1m "
        << format_number(c.rssi_at_1m_dbm, 3) << " --exponent " << format_number(c.exponent, 3)
        << '\n';
  }
}

nlohmann::json rows_json(const std::vector<CalibrationRow>& rows) {
  nlohmann::json list = nlohmann::json::array();
  for (const CalibrationRow& row : rows) {
    const localize::PathLossCalibration& c = *row.fit;
    list.push_back({{"log", row.log},
                    {"bssid", row.bssid},
                    {"rssi_at_1m_dbm", c.rssi_at_1m_dbm},
                    {"rssi_at_1m_sd_db", c.level_sd_db},
                    {"exponent", c.exponent},
                    {"exponent_sd", c.exponent_sd},
                    {"sigma_db", c.sigma_db},
                    {"heard", c.heard},
                    {"unheard", c.unheard},
                    {"nearest_m", c.nearest_m},
                    {"farthest_m", c.farthest_m}});
  }
  return {{"calibrations", list}};
}

// A fit that is singular (every scan at one distance) or not physical (an exponent <= 0, a
// sigma of 0) is refused with its reason, never suggested (issue 53 item 6): exit 2, every
// refused log and emitter listed, nothing on standard output.
void refuse_unusable_fits(const std::vector<CalibrationRow>& rows) {
  model::Diagnostics refused;
  for (const CalibrationRow& row : rows) {
    const std::string problem =
        row.fit ? localize::calibration_problem(*row.fit)
                : "no fit: fewer than 3 scans heard at least " +
                      model::format_number(localize::kCalibrationMinDistance) +
                      " m from the emitter, or their distances vary by less than 2.3 % (every "
                      "reading at one distance: the exponent is singular)";
    if (problem.empty()) continue;
    refused.error({row.log, 0, 0}, "rssi", "emitter " + row.bssid + ": " + problem,
                  "readings at distances that vary (e.g. 2 to 20 m) and fall with distance, "
                  "with the scatter of a real receiver");
  }
  refused.throw_if_errors();
}

}  // namespace

int run_calibration(const report::LocalizeOptions& options, std::ostream& out) {
  require_option(!options.truth.empty() && !options.logs.empty(), "--calibrate",
                 "needs the emitters' positions", "--calibrate --log FILE... --truth CSV");
  const std::vector<localize::EmitterTruth> truth = io::read_emitter_truth(options.truth);
  std::vector<CalibrationRow> rows;
  for (const std::string& path : options.logs) {
    const std::string text = io::read_log_text(path);
    require_option(io::log_kind_of(text, path) == io::LogKind::rssi, "--calibrate",
                   path + " is a CO2 log", "RSSI logs (t,x,y,z,bssid,rssi)");
    const localize::RssiLog log = io::parse_rssi_csv(text, path);
    for (std::size_t e = 0; e < log.emitters.size(); ++e) {
      for (const localize::EmitterTruth& t : truth) {
        if (t.bssid != log.emitters[e]) continue;
        const localize::ScanSeries scans =
            localize::scan_series(log, static_cast<int>(e), options.params.scans);
        rows.push_back({path, t.bssid,
                        localize::calibrate_path_loss(scans, t.position, options.params.walls)});
      }
    }
  }
  require_option(!rows.empty(), "--truth", "names no emitter of the logs",
                 "a CSV bssid,x,y,z holding the logs' BSSIDs");
  refuse_unusable_fits(rows);
  if (options.json) {
    out << rows_json(rows).dump(2) << '\n';
  } else {
    print_rows(rows, out);
  }
  return kOk;
}

}  // namespace rigdesign::cli
