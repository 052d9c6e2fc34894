#pragma once
// ascii bodies of both formats: one point per line, its values separated by blanks, x, y
// and z among them. Private to io.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "io/cloud/cloud_text.hpp"
#include "io/cloud/point_columns.hpp"

namespace rigdesign::io {

/// What a body line holds.
struct AsciiLayout {
  std::vector<std::string> value_names;  ///< one per value on a line, for messages
  std::array<std::size_t, 3> xyz{};      ///< positions of x, y and z on a line
};

/// Reads `count` points from the next non-blank lines of `cursor` into `collected`. Every
/// value must be a number (the ignored ones too: a garbled value means a garbled file).
/// Throws InputError (field "data", at the line) for a line with another number of values
/// or a value that is not a number, and when the lines run out first.
void read_ascii_points(const std::string& path, LineCursor& cursor, const AsciiLayout& layout,
                       std::size_t count, CollectedPoints& collected);

/// Skips `count` non-blank lines (records of an element the reader does not keep); throws
/// InputError when the lines run out first.
void skip_ascii_records(const std::string& path, LineCursor& cursor, std::size_t count,
                        const std::string& element);

}  // namespace rigdesign::io
