#include "yaml_text_spans.hpp"

#include <algorithm>

namespace rigdesign::io::yaml_text {
namespace {

bool blank_or_comment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first == std::string_view::npos || line[first] == '#';
}

}  // namespace

std::size_t offset_of(const std::string& text, int line, int column) {
  std::size_t offset = 0;
  for (int l = 0; l < line; ++l) {
    const std::size_t newline = text.find('\n', offset);
    if (newline == std::string::npos) return text.size();
    offset = newline + 1;
  }
  return std::min(text.size(), offset + static_cast<std::size_t>(column));
}

std::size_t line_begin(const std::string& text, std::size_t offset) {
  if (offset == 0) return 0;
  const std::size_t newline = text.rfind('\n', offset - 1);
  return newline == std::string::npos ? 0 : newline + 1;
}

std::size_t line_end(const std::string& text, std::size_t offset) {
  std::size_t end = text.find('\n', offset);
  if (end == std::string::npos) end = text.size();
  if (end > offset && end > 0 && text[end - 1] == '\r') --end;
  return end;
}

std::string_view line_break_at(const std::string& text, std::size_t offset) {
  const std::size_t end = line_end(text, offset);
  return end + 1 < text.size() && text[end] == '\r' ? "\r\n" : "\n";
}

std::size_t block_content_end(const std::string& text, std::size_t offset, std::size_t min_indent) {
  std::size_t content_end = line_end(text, offset);
  std::size_t next = text.find('\n', offset);
  while (next != std::string::npos && next + 1 < text.size()) {
    const std::size_t begin = next + 1;
    const std::size_t end = line_end(text, begin);
    const std::string_view line(text.data() + begin, end - begin);
    if (!blank_or_comment(line)) {
      const std::size_t indent = line.find_first_not_of(' ');
      if (indent < min_indent) break;
      content_end = end;
    }
    next = text.find('\n', begin);
  }
  return content_end;
}

std::size_t flow_end(const std::string& text, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      // Skip the quoted scalar: a backslash escapes in double quotes, '' is a quote in single.
      for (++i; i < text.size() && text[i] != c; ++i) {
        if (c == '"' && text[i] == '\\') ++i;
      }
    } else if (c == '#' && i > 0 && (text[i - 1] == ' ' || text[i - 1] == '\t')) {
      i = text.find('\n', i);
      if (i == std::string::npos) return std::string::npos;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if (c == '}' || c == ']') {
      if (--depth == 0) return i + 1;
    }
  }
  return std::string::npos;
}

}  // namespace rigdesign::io::yaml_text
