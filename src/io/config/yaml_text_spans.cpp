#include "yaml_text_spans.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <sstream>

namespace rigdesign::io::yaml_text {
namespace {

// Records every anchored node and every alias of one document, from the parser's events (a
// yaml-cpp Node resolves an alias to its anchor's node and keeps no trace of either).
class AnchorEvents : public YAML::EventHandler {
 public:
  std::map<YAML::anchor_t, SharedValue> anchored;
  std::vector<std::pair<YAML::anchor_t, TextMark>> aliases;

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnAnchor(const YAML::Mark&, const std::string& name) override { name_ = name; }
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { node(mark, anchor); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    aliases.emplace_back(anchor, TextMark{mark.line, mark.column});
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string&) override {
    node(mark, anchor);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    node(mark, anchor);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    node(mark, anchor);
  }
  void OnMapEnd() override {}

 private:
  std::string name_;  // the last anchor's name: its node's event follows it

  void node(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (anchor == YAML::NullAnchor) return;
    anchored[anchor] = {name_, {mark.line, mark.column}, {}};
  }
};

}  // namespace

std::map<TextMark, SharedValue> shared_values(const std::string& text) {
  std::istringstream stream(text);
  YAML::Parser parser(stream);
  AnchorEvents events;
  parser.HandleNextDocument(events);  // the first document: the one YAML::Load gives
  std::map<TextMark, SharedValue> shared;
  for (const auto& [anchor, mark] : events.aliases) {
    const auto found = events.anchored.find(anchor);
    if (found == events.anchored.end()) continue;  // the parser refuses an unknown alias itself
    SharedValue& value = shared.try_emplace(found->second.anchor_mark, found->second).first->second;
    value.alias_marks.push_back(mark);
  }
  return shared;
}

bool blank_or_comment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first == std::string_view::npos || line[first] == '#';
}

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
