#include "rigdesign/io/logs/log_kind.hpp"

#include "io/logs/csv_fields.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

LogKind log_kind_of(const std::string& text, const std::string& file) {
  const auto lines = csv::content_lines(text, file);
  if (lines.empty()) {
    throw model::InputError(model::Diagnostic{
        {file, 0, 0}, "data", "is empty", "an RSSI log (t,x,y,z,bssid,rssi) or a CO2 log"});
  }
  const std::string& first = lines.front().text;
  if (first.find(',') == std::string::npos) return LogKind::co2;  // the untimed x y co2_ppm form
  for (const auto& field : csv::split_fields(first, ',')) {
    if (field.text == "rssi" || field.text == "bssid") return LogKind::rssi;
    if (field.text == "co2_ppm") return LogKind::co2;
  }
  throw model::InputError(
      model::Diagnostic{{file, lines.front().number, 1},
                        "header",
                        "names neither an rssi nor a co2_ppm column",
                        "t,x,y,z,bssid,rssi or t,x,y,z,co2_ppm, or lines 'x y co2_ppm'"});
}

std::string read_log_text(const std::string& path) {
  return csv::read_text_file(path);
}

}  // namespace rigdesign::io
