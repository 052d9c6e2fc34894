#include "io/logs/csv_fields.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/text_encoding.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io::csv {
namespace {

bool is_csv_blank(char c) {
  return c == ' ' || c == '\t';
}

Field trimmed(const std::string& line, std::size_t begin, std::size_t end) {
  while (begin < end && is_csv_blank(line[begin])) ++begin;
  while (end > begin && is_csv_blank(line[end - 1])) --end;
  return {line.substr(begin, end - begin), static_cast<int>(begin) + 1};
}

}  // namespace

std::vector<Line> content_lines(const std::string& text, const std::string& file) {
  require_utf8(text, file);
  std::vector<Line> lines;
  std::size_t begin = 0;
  int number = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    ++number;
    std::string line = text.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] != '#') lines.push_back({line, number});
    if (end == text.size()) break;
    begin = end + 1;
  }
  return lines;
}

std::vector<Row> named_columns(const std::string& text, const std::string& file,
                               const std::vector<std::string>& names,
                               const std::string& expected_header) {
  const auto lines = content_lines(text, file);
  if (lines.empty())
    throw model::InputError(
        model::Diagnostic{{file, 0, 0}, "data", "is empty", "a header " + expected_header});
  const auto header = split_fields(lines.front().text, ',');
  std::vector<std::size_t> index;
  for (const std::string& name : names)
    index.push_back(require_column(header, name, file, lines.front().number, expected_header));
  std::vector<Row> rows;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const auto fields = split_fields(lines[l].text, ',');
    Row row{lines[l].number, {}};
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (index[i] >= fields.size()) {
        throw model::InputError(
            model::Diagnostic{{file, lines[l].number, static_cast<int>(lines[l].text.size()) + 1},
                              names[i],
                              "is missing",
                              "one field per header column (" + expected_header + ")"});
      }
      row.fields.push_back(fields[index[i]]);
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::optional<Field> comment_directive(const std::string& text, const std::string& key,
                                       int* line_number) {
  std::size_t begin = 0;
  int number = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    ++number;
    const std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string::npos || line[hash] != '#') continue;
    const std::size_t name = line.find_first_not_of(" \t", hash + 1);
    if (name == std::string::npos || line.compare(name, key.size(), key) != 0) continue;
    const std::size_t colon = name + key.size();
    if (colon >= line.size() || line[colon] != ':') continue;
    std::size_t value_end = line.size();
    if (value_end > colon && line[value_end - 1] == '\r') --value_end;
    *line_number = number;
    return trimmed(line, colon + 1, value_end);
  }
  return std::nullopt;
}

std::vector<Field> split_fields(const std::string& line, char separator) {
  std::vector<Field> fields;
  if (separator == ' ') {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_csv_blank(line[i])) ++i;
      if (i == line.size()) break;
      const std::size_t start = i;
      while (i < line.size() && !is_csv_blank(line[i])) ++i;
      fields.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return fields;
  }
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = line.find(separator, begin);
    if (end == std::string::npos) {
      fields.push_back(trimmed(line, begin, line.size()));
      return fields;
    }
    fields.push_back(trimmed(line, begin, end));
    begin = end + 1;
  }
}

double parse_number(const Field& field, const model::SourceLocation& where,
                    const std::string& name) {
  if (field.text.empty()) {
    throw model::InputError(model::Diagnostic{where, name, "is empty", "a number"});
  }
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(field.text.c_str(), &end);
  if (end != field.text.c_str() + field.text.size()) {
    throw model::InputError(
        model::Diagnostic{where, name, "'" + field.text + "' is not a number", "a number"});
  }
  if (!std::isfinite(value) || errno == ERANGE) {
    throw model::InputError(
        model::Diagnostic{where, name, "'" + field.text + "' is not finite", "a finite number"});
  }
  // Position columns share the clouds' limit, so cell keys and maps built on them stay sized.
  const bool coordinate = name == "x" || name == "y" || name == "z";
  if (coordinate && std::abs(value) > model::kMaxCoordinate) {
    throw model::InputError(model::Diagnostic{
        where, name, "'" + field.text + "' m lies beyond +-1e8 m",
        "coordinates within +-1e8 m (shift geo-referenced positions to a local origin)"});
  }
  return value;
}

std::size_t require_column(const std::vector<Field>& header, const std::string& name,
                           const std::string& file, int line, const std::string& expected_header) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i].text == name) return i;
  }
  throw model::InputError(model::Diagnostic{{file, line, 1},
                                            name,
                                            "column is missing from the header",
                                            "a header line naming the columns " + expected_header});
}

std::string read_text_file(const std::string& path) {
  return read_file_bytes(path, "a readable text file");
}

}  // namespace rigdesign::io::csv
