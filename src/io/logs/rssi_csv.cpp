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
    reading.rssi_dbm = number_at(5);
    if (reading.rssi_dbm > 0.0) {
      throw model::InputError(
          model::Diagnostic{{file, number, field(5).column},
                            "rssi",
                            "is " + model::format_number(reading.rssi_dbm) + " dBm, above 0 dBm",
                            "a received power in dBm, <= 0"});
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
  return log;
}

localize::RssiLog read_rssi_log(const std::string& path) {
  return parse_rssi_csv(csv::read_text_file(path), path);
}

std::string to_rssi_csv(const localize::RssiLog& log) {
  std::string text = std::string(kRssiHeader) + "\n";
  for (const localize::RssiReading& r : log.readings) {
    text += model::format_number(r.t, kDigits) + "," +
            model::format_number(r.position.x(), kDigits) + "," +
            model::format_number(r.position.y(), kDigits) + "," +
            model::format_number(r.position.z(), kDigits) + "," +
            log.emitters[static_cast<std::size_t>(r.emitter)] + "," +
            model::format_number(r.rssi_dbm, kDigits) + "\n";
  }
  return text;
}

}  // namespace rigdesign::io
