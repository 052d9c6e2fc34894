#include "rigdesign/metrics/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/metrics/mount_metrics.hpp"

namespace rigdesign::metrics {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

struct PlacedMount {
  const model::Mount* mount;
  const model::SensorMode* mode;
  geometry::MountedFov fov;
  double spacing;  // R_i at the mount's distance of interest
  double noise;    // N_i
};

std::vector<PlacedMount> place_mounts(const model::Rig& rig, const model::SensorLibrary& library,
                                      const geometry::BodyOccluder& body) {
  std::vector<PlacedMount> placed;
  for (const model::Mount& mount : rig.mounts) {
    const model::SensorMode* mode = &library.resolved_mode(mount.sensor_id, mount.mode_id);
    const double distance = rig.distance_for(mount);
    placed.push_back(
        {&mount, mode, geometry::MountedFov(*mode, mount.T_robot_sensor, body, mount.limits),
         ray_spacing(distance, mode->worst_angular_resolution()), mode->noise.sigma(distance)});
  }
  return placed;
}

geometry::RasterGrid grid_for(const geometry::SectionFrame& frame, double cell) {
  return {std::max(1, static_cast<int>(std::ceil(frame.width() / cell))),
          std::max(1, static_cast<int>(std::ceil(frame.h / cell)))};
}

double floor_share(const std::vector<geometry::IntervalSet>& floors,
                   const geometry::SectionFrame& frame) {
  geometry::IntervalSet united;
  for (const geometry::IntervalSet& floor : floors) united = united.united(floor);
  return united.length() / frame.width();
}

template <typename Value>
CoverageSummary summarize(const std::vector<AngleCoverage>& angles, Value value,
                          const model::SectorRequirement* sector = nullptr) {
  CoverageSummary summary;
  summary.min = std::numeric_limits<double>::infinity();
  int count = 0;
  int full = 0;
  for (const AngleCoverage& angle : angles) {
    if (sector != nullptr && !in_sector(*sector, angle.theta)) continue;
    const double share = value(angle);
    if (share < summary.min) {
      summary.min = share;
      summary.min_theta = angle.theta;
    }
    summary.mean += share;
    full += share >= kFullCoverage ? 1 : 0;
    ++count;
  }
  if (count == 0) return {};
  summary.mean /= count;
  summary.full_share = static_cast<double>(full) / count;
  return summary;
}

// Worst ray spacing and noise among the mounts that see part of this cross-section.
void limiting_mounts(const std::vector<PlacedMount>& mounts, AngleCoverage& angle) {
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    if (!angle.mount_sees[i]) continue;
    if (angle.coarsest_mount < 0 || mounts[i].spacing > angle.coarsest_spacing) {
      angle.coarsest_mount = static_cast<int>(i);
      angle.coarsest_spacing = mounts[i].spacing;
    }
    if (angle.noisiest_mount < 0 || mounts[i].noise > angle.noisiest_noise) {
      angle.noisiest_mount = static_cast<int>(i);
      angle.noisiest_noise = mounts[i].noise;
    }
  }
}

}  // namespace

SectionView section_view(const model::Rig& rig, const model::SensorLibrary& library, double theta,
                         const geometry::TessellationSettings& tessellation) {
  const geometry::BodyOccluder body(rig.body);
  const std::vector<PlacedMount> mounts = place_mounts(rig, library, body);
  SectionView view;
  view.frame = geometry::section_frame(body, theta, rig.distance_of_interest);
  for (const PlacedMount& mount : mounts) {
    view.mount_ids.push_back(mount.mount->id);
    view.mount_sensors.push_back(mount.mount->sensor_id);
    view.polygons.push_back(geometry::section_polygons(mount.fov, view.frame, tessellation));
    view.floors.push_back(geometry::floor_coverage(mount.fov, view.frame));
    view.origins.push_back(mount.fov.origin());
  }
  view.complete = geometry::union_area(view.polygons) / view.frame.area();
  view.floor = floor_share(view.floors, view.frame);
  return view;
}

bool in_sector(const model::SectorRequirement& sector, double theta) {
  const double offset = std::fmod(std::fmod(theta - sector.from, kTwoPi) + kTwoPi, kTwoPi);
  return offset <= sector.to - sector.from + 1e-12;
}

RigCoverage compute_coverage(const model::Rig& rig, const model::SensorLibrary& library,
                             const std::vector<model::SectorRequirement>& sectors,
                             const CoverageSettings& settings) {
  const geometry::BodyOccluder body(rig.body);
  const std::vector<PlacedMount> mounts = place_mounts(rig, library, body);
  RigCoverage result;
  result.exact = settings.exact;
  result.distance = rig.distance_of_interest;
  result.height = rig.body.area_top();
  for (const PlacedMount& mount : mounts) {
    result.mount_ids.push_back(mount.mount->id);
    result.mount_sensors.push_back(mount.mount->sensor_id);
  }

  const int steps = std::max(1, static_cast<int>(std::lround(kTwoPi / settings.step)));
  // Per angle, each mount's raster: kept for the N-1 table.
  std::vector<std::vector<geometry::SectionRaster>> rasters(mounts.size());
  for (int step = 0; step < steps; ++step) {
    AngleCoverage angle;
    angle.theta = kTwoPi * step / steps;
    const geometry::SectionFrame frame =
        geometry::section_frame(body, angle.theta, rig.distance_of_interest);
    angle.r = frame.r;
    const geometry::RasterGrid grid = grid_for(frame, settings.raster_cell);
    geometry::SectionRaster seen_once(grid);
    geometry::SectionRaster seen_twice(grid);
    std::vector<geometry::IntervalSet> floors;
    std::vector<std::vector<geometry::Polygon2>> polygons;
    for (std::size_t i = 0; i < mounts.size(); ++i) {
      geometry::SectionRaster raster = geometry::rasterize(mounts[i].fov, frame, grid);
      geometry::SectionRaster overlap = raster;
      overlap &= seen_once;
      seen_twice |= overlap;
      seen_once |= raster;
      floors.push_back(geometry::floor_coverage(mounts[i].fov, frame));
      if (settings.exact) {
        polygons.push_back(geometry::section_polygons(mounts[i].fov, frame, settings.tessellation));
      }
      angle.mount_sees.push_back(settings.exact ? !polygons.back().empty() : raster.any());
      rasters[i].push_back(std::move(raster));
    }
    angle.complete_raster = seen_once.complete_share();
    angle.floor_raster = seen_once.floor_share();
    angle.redundancy = seen_twice.complete_share();
    angle.complete =
        settings.exact ? geometry::union_area(polygons) / frame.area() : angle.complete_raster;
    angle.floor = settings.exact ? floor_share(floors, frame) : angle.floor_raster;
    result.raster_error_complete =
        std::max(result.raster_error_complete, std::abs(angle.complete - angle.complete_raster));
    result.raster_error_floor =
        std::max(result.raster_error_floor, std::abs(angle.floor - angle.floor_raster));
    limiting_mounts(mounts, angle);
    result.angles.push_back(std::move(angle));
  }

  const auto complete = [](const AngleCoverage& a) { return a.complete; };
  const auto floor = [](const AngleCoverage& a) { return a.floor; };
  result.complete = summarize(result.angles, complete);
  result.floor = summarize(result.angles, floor);
  result.complete_raster =
      summarize(result.angles, [](const AngleCoverage& a) { return a.complete_raster; });
  result.floor_raster =
      summarize(result.angles, [](const AngleCoverage& a) { return a.floor_raster; });
  for (const model::SectorRequirement& sector : sectors) {
    SectorCoverage coverage{sector, summarize(result.angles, complete, &sector),
                            summarize(result.angles, floor, &sector)};
    coverage.pass = judged_share(coverage.complete.min) >= sector.min_complete_coverage &&
                    judged_share(coverage.floor.min) >= sector.min_floor_coverage;
    result.sectors.push_back(std::move(coverage));
  }

  // N-1: the union of every other mount's raster, angle by angle.
  for (std::size_t lost = 0; lost < mounts.size(); ++lost) {
    std::vector<AngleCoverage> remaining(result.angles.size());
    for (std::size_t a = 0; a < result.angles.size(); ++a) {
      geometry::SectionRaster united(rasters[0][a].grid());
      for (std::size_t i = 0; i < mounts.size(); ++i) {
        if (i != lost) united |= rasters[i][a];
      }
      remaining[a].theta = result.angles[a].theta;
      remaining[a].complete = united.complete_share();
      remaining[a].floor = united.floor_share();
    }
    result.without_each.push_back(
        {mounts[lost].mount->id, summarize(remaining, complete), summarize(remaining, floor)});
  }
  return result;
}

BindingShare binding_share(const SectorCoverage& coverage) {
  const BindingShare complete{false, judged_share(coverage.complete.min),
                              coverage.sector.min_complete_coverage};
  const BindingShare floor{true, judged_share(coverage.floor.min),
                           coverage.sector.min_floor_coverage};
  return floor.actual - floor.required < complete.actual - complete.required ? floor : complete;
}

}  // namespace rigdesign::metrics
