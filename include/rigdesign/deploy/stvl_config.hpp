#pragma once
/// The rig's 3D sensors as spatio_temporal_voxel_layer observation sources (issue 34,
/// `export --layer stvl`): each source's clearing frustum from its mode (a depth camera's
/// pyramid, model_type 0; a 3D lidar's band, model_type 1) and the layer's voxel decay from
/// the blind-gap rule. STVL's parameters, units and frustum geometry are read from its source
/// (data/ros_parameters/spatio_temporal_voxel_layer.yaml, with file, line and commit).
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

/// STVL's frustum models (its model_type parameter).
enum class StvlModel { depth_camera = 0, lidar_3d = 1 };

struct StvlSource {
  std::size_t source = 0;  ///< index into CostmapConfig::sources
  StvlModel model = StvlModel::depth_camera;
  /// [rad] full angles as STVL reads them; a lidar's horizontal angle above 6.27 means a full
  /// turn.
  double horizontal_fov = 0.0;
  double vertical_fov = 0.0;
  /// [m] the frustum's near and far limits (for a lidar: horizontal distance from the sensor).
  double min_z = 0.0, max_z = 0.0;
  /// A lidar whose vertical FOV is not symmetric about its scan plane: released STVL clears a
  /// band symmetric about that plane, so `vertical_fov` is the largest such band inside the
  /// FOV (it never clears what the sensor cannot see). STVL builds with `vertical_fov_offset`
  /// (its PR #341) take the exact band: these two values.
  std::optional<double> exact_offset, exact_vertical_fov;
  std::string note;
};

struct StvlLayer {
  double voxel_size = 0.0;          ///< [m] the costmap's resolution
  double voxel_decay = 0.0;         ///< [s] linear decay (decay_model 0)
  std::string decay_rule;           ///< why voxel_decay is what it is
  std::vector<StvlSource> sources;  ///< the PointCloud2 sources; scanners stay in obstacle_layer
};

/// Precondition: `config` was made for `rig` (one source per mount, in order).
StvlLayer stvl_layer(const model::Rig& rig, const model::SensorLibrary& library,
                     const CostmapConfig& config);

}  // namespace rigdesign::deploy
