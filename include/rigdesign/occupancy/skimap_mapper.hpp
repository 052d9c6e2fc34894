#pragma once
/// SkiMap (De Gregorio and Di Stefano, "SkiMap: An Efficient Mapping Framework for Robot
/// Navigation", ICRA 2017), as its paper, skimap_ros's documentation and its maintainer
/// describe it (never its code): a sparse voxel map (a tree of skip lists; here an ordered map,
/// the same set semantics) whose every voxel keeps a weight, +1 for each point that falls in it;
/// a voxel is shown occupied when its weight reaches `min_voxel_weight`. There is no ray
/// casting, so nothing is ever cleared ("there is no RayCasting solution (like Octomap)
/// implemented in SkiMap", m4nh, skimap_ros issue #24): paper 3 finds it keeps the voxels the
/// actor walked through occupied.
#include <memory>
#include <string>

#include "rigdesign/occupancy/occupancy_voxel_mapper.hpp"

namespace rigdesign::occupancy {

struct SkiMapParams {
  double voxel = 0.1;  ///< [m] map_resolution (paper 3's reference row, Tab. 5)
  /// Points a voxel needs to count as occupied: skimap_ros's min_voxel_weight (its code's
  /// default is 10; paper 3's reference row is the lowest of its Tab. 6 settings).
  double min_voxel_weight = 1.0;
  double min_height = 0.1;  ///< [m] lower points are not integrated (ground)
  double z_max = 2.0;       ///< [m] top of the band; higher points are not integrated
};

/// "SkiMap 0.1 m, min weight 1".
std::string skimap_label(const SkiMapParams& params);

/// Throws std::invalid_argument for a voxel outside [0.01, 1] m or a weight below 1.
std::unique_ptr<OccupancyMapper> make_skimap_mapper(const SkiMapParams& params);

}  // namespace rigdesign::occupancy
