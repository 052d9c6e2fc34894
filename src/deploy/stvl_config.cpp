#include "rigdesign/deploy/stvl_config.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::deploy {
namespace {

// STVL's lidar frustum takes a horizontal angle above 6.27 rad as a full turn; 6.29 is what its
// examples write.
constexpr double kStvlFullTurn = 6.29;
// Degrees, for the notes.
std::string in_degrees(double radians) {
  return model::format_number(radians * 180.0 / std::numbers::pi, 4);
}

void plan_lidar_band(const model::SensorMode& mode, StvlSource& s) {
  const double low = mode.fov.elevation_min(), high = mode.fov.elevation_max();
  const double horizontal = mode.fov.horizontal();
  s.horizontal_fov = mode.fov.full_turn() ? kStvlFullTurn : horizontal;
  // STVL's band: |z| / r <= tan(vertical_fov / 2) about the sensor's plane.
  const double half = std::max(0.0, std::min(-low, high));
  s.vertical_fov = 2.0 * half;
  if (std::abs(low + high) > 1e-9) {
    // vertical_fov_offset shifts the band by r tan(offset): tan(offset) and tan(angle / 2) are
    // the mean and half the difference of tan(high) and tan(low).
    s.exact_offset = std::atan(0.5 * (std::tan(high) + std::tan(low)));
    s.exact_vertical_fov = 2.0 * std::atan(0.5 * (std::tan(high) - std::tan(low)));
    s.note = "vertical FOV " + in_degrees(low) + ".." + in_degrees(high) +
             " deg is not symmetric: released STVL clears +-" + in_degrees(half) +
             " deg (the part of the FOV symmetric about the scan plane; wider would clear what "
             "the sensor does not see); with vertical_fov_offset (STVL PR #341) use offset " +
             model::format_number(*s.exact_offset, 4) + " rad and vertical_fov_angle " +
             model::format_number(*s.exact_vertical_fov, 4) + " rad";
  }
}

}  // namespace

StvlLayer stvl_layer(const model::Rig& rig, const model::SensorLibrary& library,
                     const CostmapConfig& config) {
  StvlLayer layer;
  layer.voxel_size = config.costmap.resolution;
  double slowest_period = 0.0;
  for (std::size_t i = 0; i < config.sources.size(); ++i) {
    const SourceConfig& source = config.sources[i];
    if (source.laser_scan) continue;
    const model::Mount& mount = rig.mounts[i];
    const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
    StvlSource s;
    s.source = i;
    s.min_z = source.source.raytrace_min_range;
    s.max_z = source.source.raytrace_max_range;
    if (mode.is_camera()) {
      s.model = StvlModel::depth_camera;
      s.horizontal_fov = mode.fov.horizontal();
      s.vertical_fov = mode.fov.vertical();
    } else {
      s.model = StvlModel::lidar_3d;
      plan_lidar_band(mode, s);
    }
    slowest_period = std::max(slowest_period, 1.0 / mode.frequency);
    layer.sources.push_back(s);
  }
  // Voxels age out linearly unless a frustum clears them first: long enough to keep what a
  // blind gap hides (the blind-gap rule's keep time), else two frames of the slowest source
  // (an obstacle stays marked until the next frame has seen it again).
  if (config.memory.persistence > 0.0) {
    layer.voxel_decay = config.memory.persistence;
    layer.decay_rule = "the blind-gap rule's keep time: " + config.memory.rule;
  } else {
    layer.voxel_decay = 2.0 * slowest_period;
    layer.decay_rule = "no blind gap to remember: two frames of the slowest 3D source";
  }
  return layer;
}

}  // namespace rigdesign::deploy
