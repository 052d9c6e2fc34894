#include "rigdesign/metrics/failure_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"

namespace rigdesign::metrics {
std::vector<std::vector<std::size_t>> sectors_broken_by(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings,
    const std::vector<std::vector<bool>>& failures,
    const std::function<void(double, double)>& progress) {
  if (!settings.exact) throw std::logic_error("sectors_broken_by: the exact path only");
  const geometry::BodyOccluder body(rig.body);
  std::vector<geometry::MountedFov> fovs;
  for (const model::Mount& mount : rig.mounts) {
    fovs.emplace_back(library.resolved_mode(mount.sensor_id, mount.mode_id), mount.T_robot_sensor,
                      body, mount.housing_link, mount.limits,
                      geometry::housings_around(rig, library, mount.id));
  }
  std::vector<double> thetas;
  for (const double theta : detail::sampled_azimuths(settings)) {
    if (std::any_of(sectors.begin(), sectors.end(),
                    [&](const model::SectorRequirement& s) { return in_sector(s, theta); }))
      thetas.push_back(theta);
  }
  constexpr double kNone = std::numeric_limits<double>::infinity();
  // Per failure and sector: the smallest complete and floor share over the sector's angles.
  std::vector<std::vector<double>> complete(failures.size(),
                                            std::vector<double>(sectors.size(), kNone));
  std::vector<std::vector<double>> floor = complete;
  for (std::size_t t = 0; t < thetas.size(); ++t) {
    const geometry::SectionFrame frame =
        geometry::section_frame(body, thetas[t], rig.distance_of_interest);
    std::vector<std::vector<geometry::Polygon2>> polygons;
    std::vector<geometry::IntervalSet> floors;
    for (const geometry::MountedFov& fov : fovs) {
      polygons.push_back(geometry::section_polygons(fov, frame, settings.tessellation));
      floors.push_back(geometry::floor_coverage(fov, frame));
    }
    for (std::size_t f = 0; f < failures.size(); ++f) {
      std::vector<std::vector<geometry::Polygon2>> kept;
      geometry::IntervalSet floor_seen;
      for (std::size_t m = 0; m < fovs.size(); ++m) {
        if (failures[f][m]) continue;
        kept.push_back(polygons[m]);
        floor_seen = floor_seen.united(floors[m]);
      }
      const double complete_share = kept.empty() ? 0.0 : geometry::union_area(kept) / frame.area();
      const double floor_share = floor_seen.length() / frame.width();
      for (std::size_t s = 0; s < sectors.size(); ++s) {
        if (!in_sector(sectors[s], thetas[t])) continue;
        complete[f][s] = std::min(complete[f][s], complete_share);
        floor[f][s] = std::min(floor[f][s], floor_share);
      }
    }
    if (progress) progress(static_cast<double>(t + 1), static_cast<double>(thetas.size()));
  }
  std::vector<std::vector<std::size_t>> broken(failures.size());
  for (std::size_t f = 0; f < failures.size(); ++f) {
    for (std::size_t s = 0; s < sectors.size(); ++s) {
      // A sector no sampled angle falls in counts as seeing nothing, as in compute_coverage.
      const double seen_complete = complete[f][s] == kNone ? 0.0 : complete[f][s];
      const double seen_floor = floor[f][s] == kNone ? 0.0 : floor[f][s];
      if (!(judged_share(seen_complete) >= sectors[s].min_complete_coverage &&
            judged_share(seen_floor) >= sectors[s].min_floor_coverage))
        broken[f].push_back(s);
    }
  }
  return broken;
}

}  // namespace rigdesign::metrics
