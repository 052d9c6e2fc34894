#include "rigdesign/io/emit/yaml_emit.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <string_view>

#include "rigdesign/io/emit/xml_text.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {
namespace {

// Words YAML 1.1 (yaml-cpp, PyYAML in ROS launch) reads as booleans or null when plain.
constexpr std::array<std::string_view, 11> kSpecialWords = {
    "true", "false", "yes", "no", "on", "off", "y", "n", "null", "~", "nan"};

bool is_special_word(const std::string& text) {
  std::string lower;
  for (const char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return std::find(kSpecialWords.begin(), kSpecialWords.end(), lower) != kSpecialWords.end();
}

// Letters, digits, '_' and '/', not starting with a digit: ROS names, topics and frames, which
// YAML reads back as strings.
bool plain_safe(const std::string& text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text.front()))) return false;
  const bool name_characters = std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/';
  });
  return name_characters && !is_special_word(text);
}

}  // namespace

std::string yaml_comment(const std::string& text, const std::string& indent) {
  // YAML breaks lines at CR as at LF, and allows no other control character anywhere: a
  // CR in a rig's name would end the comment and start a key.
  std::string printable;
  for (const char c : io::utf8_repaired(text)) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\r') {
      printable += '\n';
    } else if (c == '\n' || c == '\t' || (byte >= 0x20 && byte != 0x7f)) {
      printable += c;
    } else {
      printable += '?';
    }
  }
  std::string out;
  std::istringstream lines(printable);
  for (std::string line; std::getline(lines, line);) out += indent + "# " + line + '\n';
  return out;
}

std::string yaml_scalar(const std::string& text) {
  return plain_safe(text) ? text : yaml_quoted(text);
}

std::string yaml_quoted(const std::string& text) {
  std::string escaped = "\"";
  for (const char c : io::utf8_repaired(text)) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      escaped += '\\';
      escaped += c;
    } else if (c == '\n') {
      escaped += "\\n";  // a raw line break would be folded into a space
    } else if (byte < 0x20 || byte == 0x7f) {
      char code[5];
      std::snprintf(code, sizeof code, "\\x%02x", byte);
      escaped += code;
    } else {
      escaped += c;
    }
  }
  return escaped + "\"";
}

std::string yaml_float(double value) {
  std::string text = model::exact_number(value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";  // n: inf, nan
  return text;
}

std::string yaml_bool(bool value) {
  return value ? "true" : "false";
}

void write_key(std::ostream& out, const std::string& indent, std::string_view key,
               const std::string& value, const std::string& comment) {
  out << indent << key << ": " << value;
  if (!comment.empty()) out << "  # " << comment;
  out << '\n';
}

}  // namespace rigdesign::io
