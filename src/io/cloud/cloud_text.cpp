#include "io/cloud/cloud_text.hpp"

#include <charconv>
#include <cstdlib>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

// Long enough to recognise a keyword or number, short enough to keep a message on one line.
constexpr std::size_t kLongestQuotedWord = 40;

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// from_chars refuses the leading '+' that C's strtod and most cloud writers accept.
std::string_view without_plus(std::string_view word) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '-' && word[1] != '+') word.remove_prefix(1);
  return word;
}

}  // namespace

std::optional<std::string_view> LineCursor::next() {
  if (offset_ >= bytes_.size()) return std::nullopt;
  const std::size_t end = bytes_.find('\n', offset_);
  std::string_view line =
      bytes_.substr(offset_, end == std::string_view::npos ? end : end - offset_);
  offset_ = end == std::string_view::npos ? bytes_.size() : end + 1;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  ++line_number_;
  return line;
}

void split_words(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  std::size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && is_blank(line[at])) ++at;
    const std::size_t start = at;
    while (at < line.size() && !is_blank(line[at])) ++at;
    if (at > start) words.push_back(line.substr(start, at - start));
  }
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  split_words(line, words);
  return words;
}

std::optional<double> parse_double(std::string_view word) {
  word = without_plus(word);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (end != word.data() + word.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    // strtod gives the saturated value (an infinity or a tiny number) that from_chars leaves
    // out; the word is known to be a well-formed number by now.
    return std::strtod(std::string(word).c_str(), nullptr);
  }
  if (error != std::errc()) return std::nullopt;
  return value;
}

std::optional<float> parse_float(std::string_view word) {
  word = without_plus(word);
  float value = 0.0f;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (end != word.data() + word.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    return std::strtof(std::string(word).c_str(), nullptr);
  }
  if (error != std::errc()) return std::nullopt;
  return value;
}

std::optional<std::size_t> parse_count(std::string_view word) {
  std::size_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

std::string format_float(float value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)error;  // 32 characters hold any float's shortest form
  return std::string(buffer, end);
}

std::string quote_word(std::string_view word) {
  std::string text = "'";
  for (std::size_t i = 0; i < word.size() && i < kLongestQuotedWord; ++i) {
    const unsigned char c = static_cast<unsigned char>(word[i]);
    text += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (word.size() > kLongestQuotedWord) text += "...";
  return text + "'";
}

void throw_header_error(const std::string& path, int line, const std::string& field,
                        const std::string& problem, const std::string& expected) {
  throw model::InputError(model::Diagnostic{{path, line, 1}, field, problem, expected});
}

void throw_data_error(const std::string& path, int line, const std::string& problem,
                      const std::string& expected) {
  throw model::InputError(
      model::Diagnostic{{path, line, line > 0 ? 1 : 0}, "data", problem, expected});
}

}  // namespace rigdesign::io
