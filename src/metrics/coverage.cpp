#include "rigdesign/metrics/coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/cross_section.hpp"

namespace rigdesign::metrics {
namespace {

constexpr double kCoverageTwoPi = 2 * std::numbers::pi;

using detail::PlacedMount;

std::vector<PlacedMount> place_mounts(const model::Rig& rig, const model::SensorLibrary& library,
                                      const geometry::BodyOccluder& body) {
  std::vector<PlacedMount> placed;
  for (const model::Mount& mount : rig.mounts)
    placed.push_back(detail::place_mount(rig, mount, library, body));
  return placed;
}

double floor_share(const std::vector<geometry::IntervalSet>& floors,
                   const geometry::SectionFrame& frame) {
  geometry::IntervalSet united;
  for (const geometry::IntervalSet& floor : floors) united = united.united(floor);
  return united.length() / frame.width();
}

}  // namespace

SectionView section_view(const model::Rig& rig, const model::SensorLibrary& library, double theta,
                         const geometry::TessellationSettings& tessellation) {
  const geometry::BodyOccluder body(rig.body);
  const std::vector<PlacedMount> mounts = place_mounts(rig, library, body);
  SectionView view;
  view.frame = geometry::section_frame(body, theta, rig.distance_of_interest);
  for (const PlacedMount& mount : mounts) {
    view.mount_ids.push_back(mount.id);
    view.mount_sensors.push_back(mount.sensor_id);
    view.polygons.push_back(geometry::section_polygons(mount.fov, view.frame, tessellation));
    view.floors.push_back(geometry::floor_coverage(mount.fov, view.frame));
    view.origins.push_back(mount.fov.origin());
  }
  view.complete = geometry::union_area(view.polygons) / view.frame.area();
  view.floor = floor_share(view.floors, view.frame);
  return view;
}

bool in_sector(const model::SectorRequirement& sector, double theta) {
  const double offset =
      std::fmod(std::fmod(theta - sector.from, kCoverageTwoPi) + kCoverageTwoPi, kCoverageTwoPi);
  return offset <= sector.to - sector.from + 1e-12;
}

RigCoverage compute_coverage(const model::Rig& rig, const model::SensorLibrary& library,
                             const std::vector<model::SectorRequirement>& sectors,
                             const CoverageSettings& settings) {
  const geometry::BodyOccluder body(rig.body);
  const std::vector<PlacedMount> mounts = place_mounts(rig, library, body);
  const detail::SectionSamples samples =
      detail::section_samples(body, rig.distance_of_interest, settings);
  // Per mount, its raster of every cross-section: the raster path, and the N-1 table.
  std::vector<std::vector<geometry::SectionRaster>> rasters;
  for (const PlacedMount& mount : mounts)
    rasters.push_back(detail::mount_rasters(mount.fov, samples));
  RigCoverage result;
  result.exact = settings.exact;
  result.distance = rig.distance_of_interest;
  result.height = rig.body.area_top();
  result.angles = detail::raster_angles(mounts, rasters, samples);
  if (settings.exact) {
    for (std::size_t a = 0; a < result.angles.size(); ++a) {
      AngleCoverage& angle = result.angles[a];
      const geometry::SectionFrame& frame = samples.frames[a];
      std::vector<geometry::IntervalSet> floors;
      std::vector<std::vector<geometry::Polygon2>> polygons;
      for (std::size_t i = 0; i < mounts.size(); ++i) {
        floors.push_back(geometry::floor_coverage(mounts[i].fov, frame));
        polygons.push_back(geometry::section_polygons(mounts[i].fov, frame, settings.tessellation));
        angle.mount_sees[i] = !polygons.back().empty();
      }
      angle.complete = geometry::union_area(polygons) / frame.area();
      angle.floor = floor_share(floors, frame);
      detail::limiting_mounts(mounts, angle);
      result.raster_error_complete =
          std::max(result.raster_error_complete, std::abs(angle.complete - angle.complete_raster));
      result.raster_error_floor =
          std::max(result.raster_error_floor, std::abs(angle.floor - angle.floor_raster));
    }
  }
  detail::finish_coverage(result, sectors, mounts, rasters);
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
