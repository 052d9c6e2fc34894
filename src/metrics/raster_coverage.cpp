#include "rigdesign/metrics/raster_coverage.hpp"

#include <stdexcept>

#include "coverage_parts.hpp"

namespace rigdesign::metrics {

// Held behind a pointer: the occluder points at the rig's body parts, which must not move.
struct RasterCoverage::State {
  model::Rig rig;
  model::SensorLibrary library;
  geometry::BodyOccluder body;
  detail::SectionSamples samples;
  std::vector<detail::PlacedMount> mounts;
  std::vector<std::vector<geometry::SectionRaster>> rasters;  // per mount, per angle
  int threads;

  State(const model::Rig& rig_, const model::SensorLibrary& library_,
        const CoverageSettings& settings, int threads_)
      : rig(rig_),
        library(library_),
        body(rig.body),
        samples(detail::section_samples(body, rig.distance_of_interest, settings)),
        threads(threads_) {}

  detail::PlacedMount place(const model::Mount& mount) const {
    return detail::place_mount(rig, mount, library, body);
  }
};

RasterCoverage::RasterCoverage(const model::Rig& rig, const model::SensorLibrary& library,
                               const CoverageSettings& settings, int threads)
    : state_(std::make_unique<State>(rig, library, settings, threads)) {
  for (const model::Mount& mount : rig.mounts) add_mount(mount);
}

RasterCoverage::~RasterCoverage() = default;
RasterCoverage::RasterCoverage(RasterCoverage&&) noexcept = default;
RasterCoverage& RasterCoverage::operator=(RasterCoverage&&) noexcept = default;

void RasterCoverage::set_mount(std::size_t index, const model::Mount& mount) {
  if (index >= state_->mounts.size()) throw std::out_of_range("RasterCoverage::set_mount");
  detail::PlacedMount placed = state_->place(mount);
  state_->rasters[index] = detail::mount_rasters(placed.fov, state_->samples, state_->threads);
  state_->mounts[index] = std::move(placed);
}

void RasterCoverage::add_mount(const model::Mount& mount) {
  detail::PlacedMount placed = state_->place(mount);
  state_->rasters.push_back(detail::mount_rasters(placed.fov, state_->samples, state_->threads));
  state_->mounts.push_back(std::move(placed));
}

void RasterCoverage::remove_mount(std::size_t index) {
  if (index >= state_->mounts.size()) throw std::out_of_range("RasterCoverage::remove_mount");
  const auto offset = static_cast<std::ptrdiff_t>(index);
  state_->mounts.erase(state_->mounts.begin() + offset);
  state_->rasters.erase(state_->rasters.begin() + offset);
}

std::size_t RasterCoverage::mount_count() const {
  return state_->mounts.size();
}

RigCoverage RasterCoverage::coverage(const std::vector<model::SectorRequirement>& sectors) const {
  RigCoverage result;
  result.exact = false;
  result.distance = state_->rig.distance_of_interest;
  result.height = state_->rig.body.area_top();
  result.angles = detail::raster_angles(state_->mounts, state_->rasters, state_->samples);
  detail::finish_coverage(result, sectors, state_->mounts, state_->rasters);
  return result;
}

}  // namespace rigdesign::metrics
