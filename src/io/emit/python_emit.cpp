#include "rigdesign/io/emit/python_emit.hpp"

#include <cstdio>
#include <sstream>

namespace rigdesign::io {

std::string python_string(const std::string& text) {
  std::string literal = "'";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\\' || c == '\'') {
      literal += '\\';
      literal += c;
    } else if (byte < 0x20 || byte >= 0x7f) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      literal += escaped;
    } else {
      literal += c;
    }
  }
  return literal + "'";
}

std::string python_comment(const std::string& text) {
  std::istringstream lines(text);
  std::string out;
  for (std::string line; std::getline(lines, line);) {
    std::string printable;
    for (const char c : line) {
      const auto byte = static_cast<unsigned char>(c);
      printable += byte < 0x20 || byte >= 0x7f ? '?' : c;  // ASCII: valid in any encoding
    }
    out += "# " + printable + "\n";
  }
  return out;
}

}  // namespace rigdesign::io
