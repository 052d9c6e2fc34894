#include "rigdesign/io/emit/xml_emit.hpp"

#include <algorithm>
#include <sstream>

#include "rigdesign/io/emit/xml_text.hpp"

namespace rigdesign::io {

std::string xml_attribute(const std::string& text) {
  return io::xml_escaped(text);
}

std::string xacro_literal(const std::string& text) {
  std::string literal;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] != '$') {
      literal += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && text[end] == '$') ++end;
    literal.append(text, i, end - i);
    if (end < text.size() && (text[end] == '{' || text[end] == '(')) literal += '$';
    i = end;
  }
  return xml_attribute(literal);
}

std::string xml_comment_lines(const std::string& text, const std::string& indent) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) out += indent + xml_comment_line(line) + '\n';
  return out;
}

std::string xml_comment_line(const std::string& text) {
  // XML 1.0 allows no control character but tab and line breaks, even in comments.
  std::string line;
  for (const char c : io::utf8_repaired(text)) {
    const auto byte = static_cast<unsigned char>(c);
    line += c == '\n' || c == '\r' ? ' ' : (byte < 0x20 && c != '\t') || byte == 0x7f ? '?' : c;
  }
  for (std::size_t at = line.find("--"); at != std::string::npos; at = line.find("--", at)) {
    line.replace(at, 2, "- -");
  }
  if (!line.empty() && line.back() == '-') line += ' ';  // "--->" would close it wrongly
  return line;
}

}  // namespace rigdesign::io
