#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::deploy {

deploy::DeployedConfig load_deployed_sources(const std::string& path, const model::Rig& rig,
                                             double global_frame_height) {
  const CostmapParamsFile file = load_costmap_params(path, {}, {}, global_frame_height);
  deploy::DeployedConfig config;
  config.nav2_file = path;
  config.warnings = file.warnings;
  model::Diagnostics diagnostics;
  for (std::size_t i = 0; i < file.sources.size(); ++i) {
    const std::string& name = file.sources[i].name;
    const SourceLocations& at = file.source_locations[i];
    if (rig.find_mount(name) == nullptr) {
      diagnostics.error(
          at.source, name, "names no mount of " + rig.file,
          "observation sources named after the rig's mount ids: " + model::join(rig.mount_ids()));
      continue;
    }
    config.sources.push_back({name, file.sources[i].source, at.source, at.obstacle_min_range,
                              at.obstacle_max_range, at.min_obstacle_height,
                              at.max_obstacle_height});
  }
  diagnostics.throw_if_errors();
  return config;
}

}  // namespace rigdesign::deploy
