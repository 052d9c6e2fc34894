#pragma once
// Text handling both cloud formats share: their headers are lines of whitespace-separated
// words, their ascii bodies lines of numbers, and their findings follow one pattern (header
// problems point at a line, data problems at a byte offset or point index). Private to io.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rigdesign::io {

/// Values of a cloud header's sensor viewpoint, in PCD and PLY alike: tx ty tz qw qx qy qz.
inline constexpr std::size_t kViewpointValues = 7;

/// Walks a byte buffer line by line. Keeps the 1-based number of the line last returned and
/// the offset of the first byte after it, where a binary body starts once the header ends.
class LineCursor {
 public:
  explicit LineCursor(std::string_view bytes) : bytes_(bytes) {}
  /// Starts at `offset`, a line start that `lines_before` lines precede (a body after its
  /// header), so line numbers stay the file's.
  LineCursor(std::string_view bytes, std::size_t offset, int lines_before)
      : bytes_(bytes), offset_(offset), line_number_(lines_before) {}
  /// The next line without its "\n" or "\r\n"; nullopt when the buffer is exhausted.
  std::optional<std::string_view> next();
  /// 1-based number of the line last returned (0 before the first).
  int line_number() const { return line_number_; }
  /// Offset of the first byte after the line last returned.
  std::size_t offset() const { return offset_; }

 private:
  std::string_view bytes_;
  std::size_t offset_ = 0;
  int line_number_ = 0;
};

/// Splits `line` at spaces and tabs into `words` (cleared first; reused to spare allocations
/// in ascii bodies). The views point into `line`.
void split_words(std::string_view line, std::vector<std::string_view>& words);
std::vector<std::string_view> split_words(std::string_view line);

/// A decimal number as C's strtod reads it (a leading '+', "nan" and "inf" included), the
/// whole word and nothing else; nullopt otherwise.
std::optional<double> parse_double(std::string_view word);
/// As parse_double but rounded once, straight from the decimal text, to the nearest float;
/// a value beyond float's range gives an infinity of its sign.
std::optional<float> parse_float(std::string_view word);
/// A non-negative decimal integer that fits std::size_t; nullopt otherwise.
std::optional<std::size_t> parse_count(std::string_view word);

/// The shortest decimal text that reads back to exactly `value` ("0.1", "1e-07", "nan").
std::string format_float(float value);

/// `word` in quotes for a message, cut to a readable length, with unprintable bytes shown as
/// '?' (a binary file handed over as a header shows up as garbage otherwise).
std::string quote_word(std::string_view word);

/// Throws InputError for a header problem at `line` (column 1) of `path`; `field` is the
/// header keyword concerned.
[[noreturn]] void throw_header_error(const std::string& path, int line, const std::string& field,
                                     const std::string& problem, const std::string& expected);
/// Throws InputError with field "data". `line` is the ascii body line (0 for binary bodies,
/// whose problems name the byte offset or point index in `problem` instead).
[[noreturn]] void throw_data_error(const std::string& path, int line, const std::string& problem,
                                   const std::string& expected);

}  // namespace rigdesign::io
