#pragma once
// spatio_temporal_voxel_layer's sources in a nav2 costmap file, read as the observation
// sources rigdesign checks and simulates (issue 34): STVL marks every point up to its
// `obstacle_range` (no minimum), clears within its frustum from `min_z` to `max_z`, keeps the
// height band only with the passthrough or voxel filter, and remembers a voxel for
// `voxel_decay` seconds (linear model) or for ever (any model but 0 and 1). Keys and their
// meaning: data/ros_parameters/spatio_temporal_voxel_layer.yaml.
#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"

namespace rigdesign::deploy {

void read_stvl_layer(io::MapReader& layer, const costmap::ObservationSource& defaults,
                     CostmapParamsFile& file);

}  // namespace rigdesign::deploy
