#include "rigdesign/io/logs/co2_log_reader.hpp"

#include <array>

#include "io/logs/csv_fields.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

using csv::Field;
using csv::Line;

constexpr const char* kCo2Header = "t,x,y,z,co2_ppm";

void check_ppm(double ppm, const model::SourceLocation& where) {
  if (ppm < 0.0) {
    throw model::InputError(model::Diagnostic{where, "co2_ppm",
                                              "is negative (" + model::format_number(ppm) + ")",
                                              "a concentration in ppm, >= 0"});
  }
}

localize::Co2Log parse_csv(const std::vector<Line>& lines, const std::string& file) {
  const auto header = csv::split_fields(lines.front().text, ',');
  const std::array<std::string, 5> names = {"t", "x", "y", "z", "co2_ppm"};
  std::array<std::size_t, 5> index{};
  for (std::size_t i = 0; i < names.size(); ++i) {
    index[i] = csv::require_column(header, names[i], file, lines.front().number, kCo2Header);
  }
  localize::Co2Log log;
  log.source = file;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const auto fields = csv::split_fields(lines[l].text, ',');
    std::array<double, 5> values{};
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (index[i] >= fields.size()) {
        throw model::InputError(
            model::Diagnostic{{file, lines[l].number, static_cast<int>(lines[l].text.size()) + 1},
                              names[i],
                              "is missing: the line has " + std::to_string(fields.size()) + " of " +
                                  std::to_string(header.size()) + " fields",
                              std::string("one field per header column (") + kCo2Header + ")"});
      }
      const Field& f = fields[index[i]];
      values[i] = csv::parse_number(f, {file, lines[l].number, f.column}, names[i]);
    }
    check_ppm(values[4], {file, lines[l].number, fields[index[4]].column});
    log.readings.push_back({values[0], {values[1], values[2], values[3]}, values[4]});
  }
  if (log.readings.empty()) {
    throw model::InputError(
        model::Diagnostic{{file, lines.front().number, 1},
                          "data",
                          "has a header but no readings",
                          "at least one line t,x,y,z,co2_ppm after the header"});
  }
  return log;
}

localize::Co2Log parse_untimed(const std::vector<Line>& lines, const std::string& file) {
  const std::array<std::string, 3> names = {"x", "y", "co2_ppm"};
  localize::Co2Log log;
  log.source = file;
  log.timed = false;
  for (const Line& line : lines) {
    const auto fields = csv::split_fields(line.text, ' ');
    if (fields.size() != names.size()) {
      const int column = fields.size() > names.size() ? fields[names.size()].column
                                                      : static_cast<int>(line.text.size()) + 1;
      throw model::InputError(
          model::Diagnostic{{file, line.number, column},
                            fields.size() > names.size() ? "line" : names[fields.size()],
                            "has " + std::to_string(fields.size()) + " fields",
                            "three whitespace-separated numbers 'x y co2_ppm', or a CSV header " +
                                std::string(kCo2Header)});
    }
    std::array<double, 3> values{};
    for (std::size_t i = 0; i < names.size(); ++i) {
      values[i] = csv::parse_number(fields[i], {file, line.number, fields[i].column}, names[i]);
    }
    check_ppm(values[2], {file, line.number, fields[2].column});
    log.readings.push_back(
        {static_cast<double>(log.readings.size()), {values[0], values[1], 0.0}, values[2]});
  }
  return log;
}

}  // namespace

localize::Co2Log parse_co2_log(const std::string& text, const std::string& file) {
  const auto lines = csv::content_lines(text, file);
  if (lines.empty()) {
    throw model::InputError(model::Diagnostic{
        {file, 0, 0},
        "data",
        "is empty",
        std::string("a CSV header '") + kCo2Header + "' and readings, or lines 'x y co2_ppm'"});
  }
  if (lines.front().text.find(',') != std::string::npos) return parse_csv(lines, file);
  return parse_untimed(lines, file);
}

localize::Co2Log read_co2_log(const std::string& path) {
  return parse_co2_log(csv::read_text_file(path), path);
}

}  // namespace rigdesign::io
