#pragma once
/// `nav2_costmap.yaml`, as `rigdesign export` writes it: local_costmap and global_costmap
/// parameter blocks as nav2 reads them
/// (https://docs.nav2.org/configuration/packages/configuring-costmaps.html), the Hit Layer's
/// keys under `hit_layer`. Read back by deploy/ros/nav2/costmap_params_reader.hpp.
#include <string>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/stvl_config.hpp"

namespace rigdesign::deploy {

/// The file's text; `header` opens it as comments, then the derivation notes. With `stvl` the
/// 3D sources go to a spatio_temporal_voxel_layer (`stvl_layer`) and the 2D scanners, if any,
/// to nav2's obstacle layer; `costmap --params` and `check --nav2` read only the latter.
std::string nav2_costmap_text(const deploy::CostmapConfig& config, const std::string& header,
                              const deploy::StvlLayer* stvl = nullptr);

}  // namespace rigdesign::deploy
