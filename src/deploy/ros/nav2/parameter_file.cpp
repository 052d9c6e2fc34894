#include "deploy/ros/nav2/parameter_file.hpp"

#include <utility>

namespace rigdesign::deploy::nav2 {

ParameterMap read_parameter_map(const std::string& path, model::Diagnostics& diagnostics,
                                const BlockFinder& find_block, const std::string& expected) {
  const YAML::Node root = io::load_yaml_file(path);
  std::string block_path;
  const YAML::Node block = find_block(root, block_path);
  io::MapReader reader(block, block_path, path, diagnostics, io::location_of(block, path));
  if (!reader.valid()) {
    throw model::InputError(
        model::Diagnostic{{path, 1, 1}, "(document)", "is not a map", expected});
  }
  return {block, block_path, std::move(reader)};
}

}  // namespace rigdesign::deploy::nav2
