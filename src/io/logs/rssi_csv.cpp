#include "rigdesign/io/logs/rssi_csv.hpp"

#include <array>
#include <unordered_map>

#include "io/logs/csv_fields.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

using csv::Field;

constexpr const char* kRssiHeader = "t,x,y,z,bssid,rssi";
constexpr int kDigits = 10;  // enough to reproduce positions to 0.1 um and RSSI exactly

// `# floor_dbm: -95` and `# scan_period_s: 1`: what the receiver reports down to, and how
// often it scans.
void read_receiver_comments(const std::string& text, const std::string& file,
                            localize::RssiLog* log) {
  int line = 0;
  if (const auto floor = csv::comment_directive(text, "floor_dbm", &line)) {
    const double value = csv::parse_number(*floor, {file, line, floor->column}, "floor_dbm");
    if (value > 0.0) {
      throw model::InputError(
          model::Diagnostic{{file, line, floor->column},
                            "floor_dbm",
                            "is " + model::format_number(value) + " dBm, above 0 dBm",
                            "the weakest level the receiver reports, in dBm (<= 0), e.g. -95"});
    }
    log->floor_dbm = value;
  }
  if (const auto period = csv::comment_directive(text, "scan_period_s", &line)) {
    const double value = csv::parse_number(*period, {file, line, period->column}, "scan_period_s");
    if (!(value > 0.0 && value <= 3600.0)) {
      throw model::InputError(model::Diagnostic{{file, line, period->column},
                                                "scan_period_s",
                                                "is " + model::format_number(value) + " s",
                                                "seconds between scans, in (0, 3600], e.g. 1"});
    }
    log->scan_period_s = value;
  }
}

}  // namespace

localize::RssiLog parse_rssi_csv(const std::string& text, const std::string& file) {
  const auto lines = csv::content_lines(text, file);
  if (lines.empty()) {
    throw model::InputError(
        model::Diagnostic{{file, 0, 0},
                          "data",
                          "is empty",
                          std::string("a header '") + kRssiHeader + "' and readings"});
  }
  const auto header = csv::split_fields(lines.front().text, ',');
  const std::array<std::string, 6> names = {"t", "x", "y", "z", "bssid", "rssi"};
  std::array<std::size_t, 6> index{};
  for (std::size_t i = 0; i < names.size(); ++i) {
    index[i] = csv::require_column(header, names[i], file, lines.front().number, kRssiHeader);
  }
  localize::RssiLog log;
  log.source = file;
  std::unordered_map<std::string, int> emitter_of;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const auto fields = csv::split_fields(lines[l].text, ',');
    const int number = lines[l].number;
    const auto field = [&](std::size_t column) -> const Field& {
      if (index[column] >= fields.size()) {
        const int end = static_cast<int>(lines[l].text.size()) + 1;
        throw model::InputError(
            model::Diagnostic{{file, number, end},
                              names[column],
                              "is missing: the line has " + std::to_string(fields.size()) + " of " +
                                  std::to_string(header.size()) + " fields",
                              std::string("one field per header column (") + kRssiHeader + ")"});
      }
      return fields[index[column]];
    };
    const auto number_at = [&](std::size_t column) {
      const Field& f = field(column);
      return csv::parse_number(f, {file, number, f.column}, names[column]);
    };
    localize::RssiReading reading;
    reading.t = number_at(0);
    reading.position = {number_at(1), number_at(2), number_at(3)};
    const Field& bssid = field(4);
    if (bssid.text.empty()) {
      throw model::InputError(model::Diagnostic{{file, number, bssid.column},
                                                "bssid",
                                                "is empty",
                                                "the emitter's BSSID, e.g. aa:bb:cc:dd:ee:ff"});
    }
    // An empty rssi is a scan that did not hear the emitter (below the receiver's floor).
    reading.heard = !field(5).text.empty();
    reading.rssi_dbm = reading.heard ? number_at(5) : 0.0;
    if (reading.rssi_dbm > 0.0) {
      throw model::InputError(
          model::Diagnostic{{file, number, field(5).column},
                            "rssi",
                            "is " + model::format_number(reading.rssi_dbm) + " dBm, above 0 dBm",
                            "a received power in dBm, <= 0, or empty for a scan that did not hear "
                            "the emitter"});
    }
    const auto [it, inserted] =
        emitter_of.try_emplace(bssid.text, static_cast<int>(log.emitters.size()));
    if (inserted) log.emitters.push_back(bssid.text);
    reading.emitter = it->second;
    log.readings.push_back(reading);
  }
  if (log.readings.empty()) {
    throw model::InputError(
        model::Diagnostic{{file, lines.front().number, 1},
                          "data",
                          "has a header but no readings",
                          "at least one line t,x,y,z,bssid,rssi after the header"});
  }
  read_receiver_comments(text, file, &log);
  return log;
}

localize::RssiLog read_rssi_log(const std::string& path) {
  return parse_rssi_csv(csv::read_text_file(path), path);
}

std::string to_rssi_csv(const localize::RssiLog& log) {
  std::string text;
  if (log.floor_dbm) text += "# floor_dbm: " + model::format_number(*log.floor_dbm, kDigits) + "\n";
  if (log.scan_period_s)
    text += "# scan_period_s: " + model::format_number(*log.scan_period_s, kDigits) + "\n";
  text += std::string(kRssiHeader) + "\n";
  for (const localize::RssiReading& r : log.readings) {
    text += model::format_number(r.t, kDigits) + "," +
            model::format_number(r.position.x(), kDigits) + "," +
            model::format_number(r.position.y(), kDigits) + "," +
            model::format_number(r.position.z(), kDigits) + "," +
            log.emitters[static_cast<std::size_t>(r.emitter)] + "," +
            (r.heard ? model::format_number(r.rssi_dbm, kDigits) : std::string()) + "\n";
  }
  return text;
}

}  // namespace rigdesign::io
