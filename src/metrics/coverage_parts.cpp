#include "coverage_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/metrics/mount_metrics.hpp"
#include "rigdesign/model/parallel_for.hpp"

namespace rigdesign::metrics::detail {
namespace {

geometry::RasterGrid section_raster_grid(const geometry::SectionFrame& frame, double cell) {
  return {std::max(1, static_cast<int>(std::ceil(frame.width() / cell))),
          std::max(1, static_cast<int>(std::ceil(frame.h / cell)))};
}

}  // namespace

PlacedMount place_mount(const model::Rig& rig, const model::Mount& mount,
                        const model::SensorLibrary& library, const geometry::BodyOccluder& body) {
  const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
  const double distance = rig.distance_for(mount);
  return {mount.id, mount.sensor_id,
          geometry::MountedFov(mode, mount.T_robot_sensor, body, mount.housing_link, mount.limits,
                               geometry::housings_around(rig, library, mount.id)),
          ray_spacing(distance, mode.worst_angular_resolution()), mode.noise.sigma(distance)};
}

std::vector<double> sampled_azimuths(const CoverageSettings& settings) {
  const int steps =
      std::max(1, static_cast<int>(std::lround((2 * std::numbers::pi) / settings.step)));
  std::vector<double> thetas;
  for (int step = 0; step < steps; ++step) thetas.push_back((2 * std::numbers::pi) * step / steps);
  return thetas;
}

SectionSamples section_samples(const geometry::BodyOccluder& body, double distance,
                               const CoverageSettings& settings) {
  SectionSamples samples;
  for (const double theta : sampled_azimuths(settings)) {
    samples.frames.push_back(geometry::section_frame(body, theta, distance));
    samples.grids.push_back(section_raster_grid(samples.frames.back(), settings.raster_cell));
  }
  return samples;
}

std::vector<geometry::SectionRaster> mount_rasters(const geometry::MountedFov& fov,
                                                   const SectionSamples& samples, int threads) {
  std::vector<geometry::SectionRaster> rasters(samples.frames.size());
  model::parallel_for(rasters.size(), threads, [&](std::size_t a) {
    rasters[a] = geometry::rasterize(fov, samples.frames[a], samples.grids[a]);
  });
  return rasters;
}

std::vector<AngleCoverage> raster_angles(
    const std::vector<PlacedMount>& mounts,
    const std::vector<std::vector<geometry::SectionRaster>>& rasters,
    const SectionSamples& samples) {
  std::vector<AngleCoverage> angles;
  angles.reserve(samples.frames.size());
  for (std::size_t a = 0; a < samples.frames.size(); ++a) {
    AngleCoverage angle;
    angle.theta = samples.frames[a].theta;
    angle.r = samples.frames[a].r;
    geometry::SectionRaster seen_once(samples.grids[a]);
    geometry::SectionRaster seen_twice(samples.grids[a]);
    for (std::size_t i = 0; i < mounts.size(); ++i) {
      geometry::SectionRaster overlap = rasters[i][a];
      overlap &= seen_once;
      seen_twice |= overlap;
      seen_once |= rasters[i][a];
      angle.mount_sees.push_back(rasters[i][a].any());
      angle.mount_complete.push_back(rasters[i][a].complete_share());
      angle.mount_floor.push_back(rasters[i][a].floor_share());
    }
    angle.complete_raster = seen_once.complete_share();
    angle.floor_raster = seen_once.floor_share();
    angle.redundancy = seen_twice.complete_share();
    angle.complete = angle.complete_raster;
    angle.floor = angle.floor_raster;
    limiting_mounts(mounts, angle);
    angles.push_back(std::move(angle));
  }
  return angles;
}

void limiting_mounts(const std::vector<PlacedMount>& mounts, AngleCoverage& angle) {
  angle.coarsest_mount = -1;
  angle.noisiest_mount = -1;
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

void finish_coverage(RigCoverage& result, const std::vector<model::SectorRequirement>& sectors,
                     const std::vector<PlacedMount>& mounts,
                     const std::vector<std::vector<geometry::SectionRaster>>& rasters) {
  result.mount_ids.clear();
  result.mount_sensors.clear();
  for (const PlacedMount& mount : mounts) {
    result.mount_ids.push_back(mount.id);
    result.mount_sensors.push_back(mount.sensor_id);
  }
  const auto complete = [](const AngleCoverage& a) { return a.complete; };
  const auto floor = [](const AngleCoverage& a) { return a.floor; };
  result.complete = summarize(result.angles, complete);
  result.floor = summarize(result.angles, floor);
  result.complete_raster =
      summarize(result.angles, [](const AngleCoverage& a) { return a.complete_raster; });
  result.floor_raster =
      summarize(result.angles, [](const AngleCoverage& a) { return a.floor_raster; });
  result.sectors.clear();
  for (const model::SectorRequirement& sector : sectors) {
    SectorCoverage coverage{sector, summarize(result.angles, complete, &sector),
                            summarize(result.angles, floor, &sector)};
    coverage.pass = judged_share(coverage.complete.min) >= sector.min_complete_coverage &&
                    judged_share(coverage.floor.min) >= sector.min_floor_coverage;
    result.sectors.push_back(std::move(coverage));
  }

  // N-1: the union of every other mount's raster, angle by angle.
  result.without_each.clear();
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
        {mounts[lost].id, summarize(remaining, complete), summarize(remaining, floor)});
  }
}

}  // namespace rigdesign::metrics::detail
