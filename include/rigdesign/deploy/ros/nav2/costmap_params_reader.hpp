#pragma once
/// Costmap parameters from a nav2 parameter file (docs/costmap.md, "Parameter files"): the
/// `local_costmap: local_costmap: ros__parameters:` block (or `global_costmap`, or the same
/// keys at the top of the file), with nav2's names where nav2 has the parameter and the Hit
/// Layer's own keys. Layers are found by the nav2_bringup plugin names `obstacle_layer`,
/// `voxel_layer`, `hit_layer` and `inflation_layer`. nav2 keys rigdesign does not model (topics,
/// frames, rates) are accepted and ignored; any other key is an error with "did you mean".
#include <string>
#include <vector>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/deploy/deployed_check.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::deploy {

/// Where one observation source and its limiting settings are written (the source's map
/// when a key is absent), for findings about the deployed configuration.
struct SourceLocations {
  model::SourceLocation source;
  model::SourceLocation obstacle_min_range;
  model::SourceLocation obstacle_max_range;
  model::SourceLocation min_obstacle_height;
  model::SourceLocation max_obstacle_height;
};

struct CostmapParamsFile {
  /// `defaults` with every key the file gives; checked by costmap::check_costmap_params.
  costmap::CostmapParams costmap;
  /// The layer's `observation_sources` in their order, each starting from the source defaults.
  std::vector<costmap::NamedObservationSource> sources;
  std::vector<SourceLocations> source_locations;  ///< parallel to `sources`
  bool has_sources = false;                       ///< the file names observation sources
  /// nav2's `footprint` polygon [m], empty when the file gives robot_radius; the costmap then
  /// takes its circumscribed radius as robot_radius and its inscribed one for inflation.
  std::vector<model::Vec2> footprint;
  /// A layer whose plugin class neither nav2 nor spatio_temporal_voxel_layer exports (paper
  /// 1's Hit Layer among them): nav2 would fail to configure unless the user built it.
  std::vector<model::Diagnostic> warnings;
  /// Where the window's size is written (width, else height, else the parameter block).
  model::SourceLocation window_where;
};

/// Throws InputError naming file:line:col, the key's path and the expected form for a missing
/// file, a malformed value, an unknown key, a source named but not given, or parameters no
/// costmap accepts. The file's heights (sources' bands, the voxel column) are in its global
/// frame, `global_frame_height` [m] above the floor; the result's are above the floor.
CostmapParamsFile load_costmap_params(const std::string& path,
                                      const costmap::CostmapParams& defaults,
                                      const costmap::ObservationSource& source_defaults,
                                      double global_frame_height = 0.0);

/// The nav2 observation sources of `path` (load_costmap_params) as deployed, each named
/// after a mount of `rig` (as `rigdesign export` names them); a source that names no mount is
/// an InputError at its key.
deploy::DeployedConfig load_deployed_sources(const std::string& path, const model::Rig& rig,
                                             double global_frame_height = 0.0);

}  // namespace rigdesign::deploy
