#pragma once
// The pieces both coverage paths share (private to metrics): a mount placed against the body,
// the sampled cross-sections, one mount's rasters of them, and the summaries, sectors and N-1
// table computed from per-angle shares. compute_coverage runs them once; RasterCoverage keeps
// each mount's rasters so that an edit recomputes only the mount it changed.
#include <limits>
#include <string>
#include <vector>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/geometry/section_raster.hpp"
#include "rigdesign/metrics/coverage.hpp"

namespace rigdesign::metrics::detail {

struct PlacedMount {
  std::string id;
  std::string sensor_id;
  geometry::MountedFov fov;
  double spacing;  // R_i at the mount's distance of interest
  double noise;    // N_i
};

PlacedMount place_mount(const model::Rig& rig, const model::Mount& mount,
                        const model::SensorLibrary& library, const geometry::BodyOccluder& body);

/// The azimuths coverage samples [rad]: 0 and every settings.step (rounded to divide 360 deg).
std::vector<double> sampled_azimuths(const CoverageSettings& settings);

/// The cross-sections every mount is cut with: per sampled azimuth, its frame and raster grid.
struct SectionSamples {
  std::vector<geometry::SectionFrame> frames;
  std::vector<geometry::RasterGrid> grids;
};

SectionSamples section_samples(const geometry::BodyOccluder& body, double distance,
                               const CoverageSettings& settings);

/// `fov`'s raster of every sampled cross-section, the sections shared among `threads`.
std::vector<geometry::SectionRaster> mount_rasters(const geometry::MountedFov& fov,
                                                   const SectionSamples& samples, int threads = 1);

/// Per angle, the raster shares of the union of `rasters` (per mount, per angle): complete,
/// floor, redundancy and which mounts see the section; the limiting mounts. The exact shares
/// are set to the raster's (the exact path overwrites them).
std::vector<AngleCoverage> raster_angles(
    const std::vector<PlacedMount>& mounts,
    const std::vector<std::vector<geometry::SectionRaster>>& rasters,
    const SectionSamples& samples);

/// Worst ray spacing and noise among the mounts that see part of the cross-section.
void limiting_mounts(const std::vector<PlacedMount>& mounts, AngleCoverage& angle);

/// Fills `result`'s summaries, sector verdicts and N-1 table from its angles and the rasters.
void finish_coverage(RigCoverage& result, const std::vector<model::SectorRequirement>& sectors,
                     const std::vector<PlacedMount>& mounts,
                     const std::vector<std::vector<geometry::SectionRaster>>& rasters);

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

}  // namespace rigdesign::metrics::detail
