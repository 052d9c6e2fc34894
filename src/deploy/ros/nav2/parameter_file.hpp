#pragma once
// The start every reader of a nav2 parameter file shares (the costmap's, the collision
// monitor's): the YAML read, the map holding the parameters found, and a clear error when
// there is no map to read.
#include <functional>
#include <string>

#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::deploy::nav2 {

/// Finds the map holding the parameters under the file's root and sets `path` to the keys
/// that lead there (empty: the root itself).
using BlockFinder = std::function<YAML::Node(const YAML::Node& root, std::string& path)>;

/// The map holding a file's parameters: its node, the keys that lead there, and a reader of it.
struct ParameterMap {
  YAML::Node block;
  std::string block_path;
  io::MapReader reader;
};

/// The parameters of the nav2 file at `path`, read into `diagnostics`. Throws InputError at
/// the file's start, expecting `expected`, when they are not a map.
ParameterMap read_parameter_map(const std::string& path, model::Diagnostics& diagnostics,
                                const BlockFinder& find_block, const std::string& expected);

}  // namespace rigdesign::deploy::nav2
