#pragma once
// Splitting log lines into located fields and parsing numbers with file:line:column errors,
// shared by the RSSI, CO2 and ground-truth readers. Private to src/localize.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rigdesign/model/source_location.hpp"

namespace rigdesign::io::csv {

struct Field {
  std::string text;  ///< trimmed of spaces and tabs
  int column = 1;    ///< 1-based character column where the field starts
};

/// A non-blank, non-comment line of a text file with its 1-based number.
struct Line {
  std::string text;
  int number = 0;
};

/// Lines of `text` without blank lines and '#' comments; CR before LF removed. Throws
/// InputError naming `file` when the text is not UTF-8.
std::vector<Line> content_lines(const std::string& text, const std::string& file);

/// Fields separated by `separator` (',' for CSV; ' ' means runs of spaces or tabs).
std::vector<Field> split_fields(const std::string& line, char separator);

/// The field as a finite number; throws InputError at `where` naming `name` otherwise.
double parse_number(const Field& field, const model::SourceLocation& where,
                    const std::string& name);

/// Index of `name` in the header, or throws InputError (line 1) listing what is required.
std::size_t require_column(const std::vector<Field>& header, const std::string& name,
                           const std::string& file, int line, const std::string& expected_header);

/// One data line of a table: its number and the fields of the asked-for columns, in the order
/// they were asked for.
struct Row {
  int number = 0;
  std::vector<Field> fields;
};

/// The data lines of a comma-separated table whose header (its first content line) names every
/// one of `names`, in any order. InputError naming `file` for an empty text, a column missing
/// from the header or a line without one of the columns (at the line's end).
std::vector<Row> named_columns(const std::string& text, const std::string& file,
                               const std::vector<std::string>& names,
                               const std::string& expected_header);

/// The value of a `# key: value` comment line (the first one), located for messages; empty
/// when the text has none. Keys are matched whole and case-sensitively.
std::optional<Field> comment_directive(const std::string& text, const std::string& key,
                                       int* line_number);

/// The whole file as a string; InputError (field "file") when it cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace rigdesign::io::csv
