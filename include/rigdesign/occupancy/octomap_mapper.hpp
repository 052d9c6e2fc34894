#pragma once
/// OctoMap (Hornung et al., 2013), the real library (Debian's liboctomap-dev 1.9), configured as
/// paper 3 ran it through octomap_server: one log-odds update per voxel per inserted cloud (a
/// voxel both on a ray and at an end point counts as hit), clamping at octomap_server's 0.12 and
/// 0.97, occupied at probability >= 0.5. Each sensor's cloud goes in from that sensor's origin.
/// Points below `min_height` clear along their rays and never mark, as octomap_server treats
/// ground points and as the other mappers of the comparison do.
///
/// The updates are applied as log-odds through OcTree::updateNode(key, float), not through
/// setProbHit/setProbMiss, so that paper 3's edge settings keep their meaning: hit 1 (log-odds
/// +infinity, which OctoMap's clamping turns into "one hit sets the clamping maximum") and
/// miss 0.7 (a free-space update that raises the voxel; the library's setter asserts against it).
#include <memory>
#include <string>

#include "rigdesign/occupancy/occupancy_voxel_mapper.hpp"

namespace rigdesign::occupancy {

struct OctoMapParams {
  double resolution = 0.1;  ///< [m] paper 3's reference row (Tabs. 2-4)
  /// Probability of a hit. Paper 3 advocates 1 (its reference row, see docs/occupancy.md);
  /// OctoMap's library default is 0.7.
  double hit = 1.0;
  double miss = 0.4;        ///< probability of a miss (OctoMap's default)
  double clamp_min = 0.12;  ///< octomap_server's sensor_model/min
  double clamp_max = 0.97;  ///< octomap_server's sensor_model/max
  double min_height = 0.1;  ///< [m] lower points clear but never mark
  double z_max = 2.0;       ///< [m] top of the scored band
};

/// "OctoMap 0.1 m, hit 1, miss 0.4".
std::string octomap_label(const OctoMapParams& params);

/// Throws std::invalid_argument for a resolution outside [0.01, 1] m or a probability outside
/// [0, 1] (clamps must also satisfy 0 < min < 0.5 < max < 1).
std::unique_ptr<OccupancyMapper> make_octomap_mapper(const OctoMapParams& params);

}  // namespace rigdesign::occupancy
