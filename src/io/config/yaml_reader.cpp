#include "rigdesign/io/config/yaml_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "io/text_encoding.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/closest_name.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {
namespace {

std::string describe_kind(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null: return "empty";
    case YAML::NodeType::Scalar: return "'" + node.Scalar() + "'";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    case YAML::NodeType::Undefined: return "missing";
  }
  return "?";
}

std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& allowed) {
  const std::string closest = model::closest_name(key, allowed);
  return closest.empty() ? "unknown field" : "unknown field (did you mean '" + closest + "'?)";
}

}  // namespace

YAML::Node load_yaml_file(const std::string& path) {
  return parse_yaml_text(read_file_bytes(path, "a readable YAML file"), path);
}

YAML::Node parse_yaml_text(const std::string& text, const std::string& path) {
  require_utf8(text, path);
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw model::InputError(model::Diagnostic{{path, e.mark.line + 1, e.mark.column + 1},
                                              "(syntax)",
                                              "YAML syntax error: " + e.msg,
                                              "well-formed YAML"});
  }
}

model::SourceLocation location_of(const YAML::Node& node, const std::string& file) {
  if (!node.IsDefined()) return {file, 0, 0};
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {file, 0, 0};
  return {file, mark.line + 1, mark.column + 1};
}

MapReader::MapReader(YAML::Node node, std::string path, std::string file,
                     model::Diagnostics& diagnostics, model::SourceLocation named_at)
    : node_(std::move(node)),
      path_(std::move(path)),
      file_(std::move(file)),
      diagnostics_(&diagnostics) {
  where_ = named_at.line != 0 ? named_at : location_of(node_, file_);
  valid_ = node_.IsMap();
}

model::SourceLocation MapReader::key_location(const std::string& key) const {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == key) return location_of(it->first, file_);
  }
  return where_;
}

bool MapReader::has(const std::string& key) const {
  read_.insert(key);
  return valid_ && node_[key].IsDefined() && !node_[key].IsNull();
}

model::SourceLocation MapReader::location(const std::string& key) const {
  if (!valid_) return where_;
  const model::SourceLocation at_key = location_of(node_[key], file_);
  return at_key.line == 0 ? where_ : at_key;
}

std::string MapReader::field(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

YAML::Node MapReader::node(const std::string& key) {
  read_.insert(key);
  if (!valid_) return YAML::Node(YAML::NodeType::Undefined);
  return node_[key];
}

void MapReader::error(const std::string& key, const std::string& problem,
                      const std::string& expected) {
  diagnostics_->error(location(key), field(key), problem, expected);
}

bool MapReader::present(const std::string& key, Need need, const std::string& expected) {
  read_.insert(key);
  if (!valid_) return false;
  if (has(key)) return true;
  if (need == Need::required) error(key, "missing", expected);
  return false;
}

std::optional<double> MapReader::number(const std::string& key, Need need,
                                        const std::string& expected) {
  if (!present(key, need, expected)) return std::nullopt;
  return sequence_number(node_[key], field(key), file_, expected, *diagnostics_);
}

std::optional<int> MapReader::integer(const std::string& key, Need need,
                                      const std::string& expected) {
  if (!present(key, need, expected)) return std::nullopt;
  const YAML::Node value = node_[key];
  int parsed = 0;
  if (!value.IsScalar() || !YAML::convert<int>::decode(value, parsed)) {
    error(key, "is " + describe_kind(value), expected);
    return std::nullopt;
  }
  return parsed;
}

std::optional<std::string> MapReader::text(const std::string& key, Need need,
                                           const std::string& expected) {
  if (!present(key, need, expected)) return std::nullopt;
  const YAML::Node value = node_[key];
  if (!value.IsScalar()) {
    error(key, "is " + describe_kind(value), expected);
    return std::nullopt;
  }
  return value.Scalar();
}

std::optional<bool> MapReader::boolean(const std::string& key, Need need) {
  const std::string expected = "true or false";
  if (!present(key, need, expected)) return std::nullopt;
  const YAML::Node value = node_[key];
  bool parsed = false;
  if (!value.IsScalar() || !YAML::convert<bool>::decode(value, parsed)) {
    error(key, "is " + describe_kind(value), expected);
    return std::nullopt;
  }
  return parsed;
}

std::optional<std::vector<double>> MapReader::numbers(const std::string& key, Need need,
                                                      std::size_t min_size, std::size_t max_size,
                                                      const std::string& expected) {
  if (!present(key, need, expected)) return std::nullopt;
  const YAML::Node value = node_[key];
  if (!value.IsSequence() || value.size() < min_size || value.size() > max_size) {
    const std::string kind =
        value.IsSequence() ? "a list of " + std::to_string(value.size()) : describe_kind(value);
    error(key, "is " + kind, expected);
    return std::nullopt;
  }
  std::vector<double> parsed;
  bool all_valid = true;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const auto element = sequence_number(value[i], field(key) + "[" + std::to_string(i) + "]",
                                         file_, expected, *diagnostics_);
    all_valid = all_valid && element.has_value();
    parsed.push_back(element.value_or(0.0));
  }
  if (!all_valid) return std::nullopt;
  return parsed;
}

std::optional<std::size_t> MapReader::choice(const std::string& key, Need need,
                                             const std::vector<std::string>& names) {
  const std::string expected = "one of: " + model::join(names, ", ");
  const auto value = text(key, need, expected);
  if (!value) return std::nullopt;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == *value) return i;
  }
  error(key, "unknown value '" + *value + "'", expected);
  return std::nullopt;
}

std::optional<MapReader> MapReader::map(const std::string& key, Need need,
                                        const std::string& expected) {
  if (!present(key, need, expected)) return std::nullopt;
  const YAML::Node value = node_[key];
  if (!value.IsMap()) {
    error(key, "is " + describe_kind(value), expected);
    return std::nullopt;
  }
  return MapReader(value, field(key), file_, *diagnostics_, key_location(key));
}

std::vector<MapReader> MapReader::maps(const std::string& key, Need need,
                                       const std::string& expected) {
  std::vector<MapReader> elements;
  if (!present(key, need, expected)) return elements;
  const YAML::Node value = node_[key];
  if (!value.IsSequence()) {
    error(key, "is " + describe_kind(value), expected);
    return elements;
  }
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string element_field = field(key) + "[" + std::to_string(i) + "]";
    if (!value[i].IsMap()) {
      diagnostics_->error(location_of(value[i], file_), element_field,
                          "is " + describe_kind(value[i]), "a map");
      continue;
    }
    elements.emplace_back(value[i], element_field, file_, *diagnostics_);
  }
  return elements;
}

void MapReader::require(bool ok, const std::string& key, const std::string& problem,
                        const std::string& expected) {
  if (!ok) error(key, problem, expected);
}

void MapReader::accept_keys(const std::vector<std::string>& keys) {
  read_.insert(keys.begin(), keys.end());
}

void MapReader::reject_unknown_keys() {
  reject_keys_other_than(std::vector<std::string>(read_.begin(), read_.end()));
}

void MapReader::reject_keys_other_than(const std::vector<std::string>& allowed) {
  if (!valid_) return;
  std::map<std::string, int> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "?";
    const model::SourceLocation where = location_of(it->first, file_);
    if (++seen[key] == 2) {
      diagnostics_->error(where, field(key), "given twice", "each key once");
      continue;
    }
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::vector<std::string> sorted(allowed.begin(), allowed.end());
      std::sort(sorted.begin(), sorted.end());
      diagnostics_->error(where, field(key), unknown_key_problem(key, sorted),
                          "one of: " + model::join(sorted, ", "));
    }
  }
}

std::optional<double> sequence_number(const YAML::Node& element, const std::string& field,
                                      const std::string& file, const std::string& expected,
                                      model::Diagnostics& diagnostics) {
  double parsed = 0.0;
  if (!element.IsScalar() || !YAML::convert<double>::decode(element, parsed)) {
    diagnostics.error(location_of(element, file), field, "is " + describe_kind(element), expected);
    return std::nullopt;
  }
  if (!std::isfinite(parsed)) {
    diagnostics.error(location_of(element, file), field,
                      "is " + describe_kind(element) + ", not a finite number", expected);
    return std::nullopt;
  }
  return parsed;
}

MapReader read_document_map(const std::string& path, model::Diagnostics& diagnostics,
                            const std::string& expected) {
  return read_document_map(load_yaml_file(path), path, diagnostics, expected);
}

MapReader read_document_map(YAML::Node document, const std::string& path,
                            model::Diagnostics& diagnostics, const std::string& expected) {
  MapReader top(std::move(document), "", path, diagnostics, {path, 1, 1});
  if (!top.valid()) {
    throw model::InputError(
        model::Diagnostic{{path, 1, 1}, "(document)", "is not a map", expected});
  }
  return top;
}

}  // namespace rigdesign::io
