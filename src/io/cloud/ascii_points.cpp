#include "io/cloud/ascii_points.hpp"

#include <optional>
#include <string_view>

namespace rigdesign::io {
namespace {

// The next line holding any value; nullopt at the buffer's end.
std::optional<std::string_view> next_record(LineCursor& cursor,
                                            std::vector<std::string_view>& words) {
  while (const auto line = cursor.next()) {
    split_words(*line, words);
    if (!words.empty()) return line;
  }
  return std::nullopt;
}

std::string names_of(const AsciiLayout& layout) {
  std::string text;
  for (const std::string& name : layout.value_names) text += (text.empty() ? "" : " ") + name;
  return text;
}

}  // namespace

void read_ascii_points(const std::string& path, LineCursor& cursor, const AsciiLayout& layout,
                       std::size_t count, CollectedPoints& collected) {
  const std::size_t values_per_line = layout.value_names.size();
  const std::string expected =
      std::to_string(values_per_line) + " numbers per line (" + names_of(layout) + ")";
  constexpr int kNotACoordinate = -1;
  std::vector<int> axis_at(values_per_line, kNotACoordinate);
  for (int axis = 0; axis < 3; ++axis) axis_at[layout.xyz[static_cast<std::size_t>(axis)]] = axis;

  std::vector<std::string_view> words;
  model::Point3f point = model::Point3f::Zero();
  for (std::size_t index = 0; index < count; ++index) {
    if (!next_record(cursor, words)) {
      throw_data_error(path, 0,
                       "the ascii body ends after " + std::to_string(index) + " of " +
                           std::to_string(count) + " points",
                       "one line per declared point");
    }
    const std::string which = "point " + std::to_string(index);
    if (words.size() != values_per_line) {
      throw_data_error(path, cursor.line_number(),
                       which + " has " + std::to_string(words.size()) + " values", expected);
    }
    for (std::size_t i = 0; i < values_per_line; ++i) {
      // x, y, z are rounded to float straight from the text, so writing the shortest form
      // and reading it back gives the same float.
      const int axis = axis_at[i];
      bool is_number = false;
      if (axis == kNotACoordinate) {
        is_number = parse_double(words[i]).has_value();
      } else if (const auto value = parse_float(words[i])) {
        point[axis] = *value;
        is_number = true;
      }
      if (!is_number) {
        throw_data_error(
            path, cursor.line_number(),
            which + ": " + layout.value_names[i] + " is " + quote_word(words[i]) + ", not a number",
            expected);
      }
    }
    collected.keep_if_finite(point);
  }
}

void skip_ascii_records(const std::string& path, LineCursor& cursor, std::size_t count,
                        const std::string& element) {
  std::vector<std::string_view> words;
  for (std::size_t index = 0; index < count; ++index) {
    if (!next_record(cursor, words)) {
      throw_data_error(path, 0,
                       "the ascii body ends after " + std::to_string(index) + " of " +
                           std::to_string(count) + " " + element + " records",
                       "one line per declared record");
    }
  }
}

}  // namespace rigdesign::io
