#pragma once
// Typed, located access to a YAML map for the loaders. Every accessor records what it read,
// reports what is missing or malformed to Diagnostics with file:line:col and the field's
// dotted path, and keeps going so one run lists every problem in a file. Private to io:
// yaml-cpp does not leak into public headers.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

enum class Need { required, optional };

/// Loads and parses a YAML file; missing files and syntax errors throw InputError.
YAML::Node load_yaml_file(const std::string& path);
/// As load_yaml_file, on `text` already read from `path` (which names it in errors).
YAML::Node parse_yaml_text(const std::string& text, const std::string& path);

/// 1-based location of a node (or of the file when the node carries no mark).
model::SourceLocation location_of(const YAML::Node& node, const std::string& file);

class MapReader {
 public:
  /// `node` should be a map. `named_at` is where the map is named (its key in the parent,
  /// or the file's start): findings about the whole map, such as a missing field, point
  /// there; without it they point at the map's first entry.
  MapReader(YAML::Node node, std::string path, std::string file, model::Diagnostics& diagnostics,
            model::SourceLocation named_at = {});

  bool valid() const { return valid_; }
  /// Whether `key` is present and not null; asking marks the key as known.
  bool has(const std::string& key) const;
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  model::Diagnostics& diagnostics() const { return *diagnostics_; }
  model::SourceLocation location() const { return where_; }
  /// Location of the value under `key`, or of this map when the key is absent.
  model::SourceLocation location(const std::string& key) const;
  std::string field(const std::string& key) const;

  /// The raw node under `key` (undefined when absent); marks the key as read.
  YAML::Node node(const std::string& key);

  std::optional<double> number(const std::string& key, Need need, const std::string& expected);
  std::optional<int> integer(const std::string& key, Need need, const std::string& expected);
  std::optional<std::string> text(const std::string& key, Need need,
                                  const std::string& expected = "a string");
  std::optional<bool> boolean(const std::string& key, Need need);
  /// A list of finite numbers with a length in [min_size, max_size].
  std::optional<std::vector<double>> numbers(const std::string& key, Need need,
                                             std::size_t min_size, std::size_t max_size,
                                             const std::string& expected);
  /// A scalar that must be one of `names`; returns its index.
  std::optional<std::size_t> choice(const std::string& key, Need need,
                                    const std::vector<std::string>& names);
  std::optional<MapReader> map(const std::string& key, Need need,
                               const std::string& expected = "a map");
  /// Each element of a list of maps, with path "key[i]".
  std::vector<MapReader> maps(const std::string& key, Need need,
                              const std::string& expected = "a list of maps");

  /// Records an error at `key` unless `ok`.
  void require(bool ok, const std::string& key, const std::string& problem,
               const std::string& expected);
  /// Marks `keys` as known without reading them: keys a reader reads past.
  void accept_keys(const std::vector<std::string>& keys);
  /// Reports keys not read so far and keys given twice.
  void reject_unknown_keys();
  /// Reports keys outside `allowed` (for maps that are read on behalf of another).
  void reject_keys_other_than(const std::vector<std::string>& allowed);

 private:
  void error(const std::string& key, const std::string& problem, const std::string& expected);
  model::SourceLocation key_location(const std::string& key) const;
  bool present(const std::string& key, Need need, const std::string& expected);

  YAML::Node node_;
  std::string path_;
  std::string file_;
  model::Diagnostics* diagnostics_;
  model::SourceLocation where_;
  bool valid_ = false;
  mutable std::set<std::string> read_;  // keys the loader knows: asked for or read
};

/// The top-level map of the YAML file at `path`, reporting to `diagnostics` (which must outlive
/// it). Throws InputError for a missing file, a syntax error, or a document that is not a map
/// (at 1:1, field "(document)", with `expected` saying what the file should hold).
MapReader read_document_map(const std::string& path, model::Diagnostics& diagnostics,
                            const std::string& expected);
/// As above, on a document already parsed from `path` (parse_yaml_text).
MapReader read_document_map(YAML::Node document, const std::string& path,
                            model::Diagnostics& diagnostics, const std::string& expected);

/// Reads one element of a sequence as a scalar number, with its own location.
std::optional<double> sequence_number(const YAML::Node& element, const std::string& field,
                                      const std::string& file, const std::string& expected,
                                      model::Diagnostics& diagnostics);

}  // namespace rigdesign::io
