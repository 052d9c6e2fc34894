#include "rigdesign/deploy/blind_gap_sources.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {
namespace {

// [m] how far beyond the body a grazing obstacle stands, and the step along its approach.
constexpr double kGrazingGap = 0.05;
constexpr double kApproachStep = 0.05;

// Whether `mount` measures an obstacle grazing the body (a vertical line one cell outside it,
// the height of the area to perceive) anywhere on its approach to the gap: from the distance
// of interest down to where it enters the gap, on the side of `last_seen` (the pass the
// blind-gap rule sized). These sources keep what then enters the gap.
bool sees_approach(const model::Rig& rig, const geometry::MountedFov& fov,
                   const metrics::AngleCoverage& last_seen, double distance) {
  const double side = std::sin(last_seen.theta) >= 0.0 ? 1.0 : -1.0;
  const double lateral = last_seen.r + kGrazingGap;
  // x = lateral cot(azimuth): where the obstacle stands when seen last before the gap.
  const double sine = std::abs(std::sin(last_seen.theta));
  const double x_enter = sine > 1e-9 ? lateral * std::cos(last_seen.theta) / sine : 0.0;
  const double x_far = std::sqrt(std::max(0.0, distance * distance - lateral * lateral));
  for (int step = 0; x_enter + step * kApproachStep <= x_far + 1e-9; ++step) {
    const model::Vec3 foot(x_enter + step * kApproachStep, side * lateral, 0.0);
    if (!fov.covered_along(foot, model::Vec3::UnitZ(), 0.0, rig.body.area_top(),
                           std::atan2(foot.y(), foot.x()))
             .empty())
      return true;
  }
  return false;
}

}  // namespace

void keep_blind_gap_clouds(const model::Rig& rig, const model::SensorLibrary& library,
                           const metrics::RigCoverage& coverage, CostmapConfig& config, bool stvl) {
  const geometry::BodyOccluder body(rig.body);
  std::vector<std::string> kept;
  std::vector<bool> remembered(config.memory.gaps.size(), false);
  for (std::size_t m = 0; m < config.sources.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    const geometry::MountedFov fov(library.resolved_mode(mount.sensor_id, mount.mode_id),
                                   mount.T_robot_sensor, body, mount.housing_link, {},
                                   geometry::housings_around(rig, library, mount.id));
    double& persistence = config.sources[m].source.observation_persistence;
    for (std::size_t g = 0; g < config.memory.gaps.size(); ++g) {
      const BlindGap& gap = config.memory.gaps[g];
      if (gap.last_seen < 0) continue;
      const metrics::AngleCoverage& seen = coverage.angles[static_cast<std::size_t>(gap.last_seen)];
      if (!sees_approach(rig, fov, seen, rig.distance_for(mount))) continue;
      persistence = std::max(persistence, gap.persistence);
      remembered[g] = true;
    }
    if (persistence > 0.0 && (!stvl || config.sources[m].laser_scan))
      kept.push_back(config.sources[m].mount_id + " " + model::format_number(persistence, 3) +
                     " s");
  }
  for (std::size_t g = 0; g < config.memory.gaps.size(); ++g) {
    if (remembered[g]) continue;
    const BlindGap& gap = config.memory.gaps[g];
    config.notes.push_back("warning: no source sees an obstacle before it enters the blind gap " +
                           model::format_number(model::rad_to_deg(gap.from), 3) + ".." +
                           model::format_number(model::rad_to_deg(gap.to), 3) +
                           " deg, so nothing can remember it (export --hit-layer-plugin does not "
                           "help either)");
  }
  const std::string stvl_memory =
      stvl ? "; the 3D sources remember in stvl_layer through voxel_decay" : "";
  if (kept.empty()) {
    if (stvl) config.notes.push_back("blind memory" + stvl_memory + ": " + config.memory.rule);
    return;
  }
  config.notes.push_back("blind memory: observation_persistence " + model::join(kept) +
                         ", the sources that see an obstacle grazing the body on its approach to "
                         "a blind gap" +
                         stvl_memory + ": " + config.memory.rule);
}

}  // namespace rigdesign::deploy
