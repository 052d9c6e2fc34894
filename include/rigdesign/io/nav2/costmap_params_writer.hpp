#pragma once
/// `nav2_costmap.yaml`, as `rigdesign export` writes it: local_costmap and global_costmap
/// parameter blocks as nav2 reads them
/// (https://docs.nav2.org/configuration/packages/configuring-costmaps.html), the Hit Layer's
/// keys under `hit_layer`. Read back by io/nav2/costmap_params_reader.hpp.
#include <string>

#include "rigdesign/deploy/costmap_config.hpp"

namespace rigdesign::io {

/// The file's text; `header` opens it as comments, then the derivation notes.
std::string nav2_costmap_text(const deploy::CostmapConfig& config, const std::string& header);

}  // namespace rigdesign::io
