#include "io/emit/xml_emit.hpp"

#include <algorithm>
#include <sstream>

#include "rigdesign/model/xml_text.hpp"

namespace rigdesign::io {

std::string xml_attribute(const std::string& text) {
  return model::xml_escaped(text);
}

std::string xml_comment_lines(const std::string& text, const std::string& indent) {
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) out += indent + xml_comment_line(line) + '\n';
  return out;
}

std::string xml_comment_line(const std::string& text) {
  std::string line = text;
  std::replace(line.begin(), line.end(), '\n', ' ');
  for (std::size_t at = line.find("--"); at != std::string::npos; at = line.find("--", at)) {
    line.replace(at, 2, "- -");
  }
  return line;
}

}  // namespace rigdesign::io
