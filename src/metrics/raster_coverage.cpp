#include "rigdesign/metrics/raster_coverage.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"

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

  void refresh(std::size_t index) {
    mounts[index] = place(rig.mounts[index]);
    rasters[index] = detail::mount_rasters(mounts[index].fov, samples, threads);
  }

  // A housing moved from `before` to `after` (either may be nothing) changes what the other
  // mounts see: each whose view either place may reach is placed and cut again.
  void rehouse(const std::optional<model::Mount>& before, const std::optional<model::Mount>& after,
               std::size_t skip) {
    std::vector<model::BodyPart> moved;
    for (const auto* mount : {&before, &after}) {
      if (!*mount) continue;
      if (auto part = geometry::mount_housing(**mount, library)) moved.push_back(std::move(*part));
    }
    if (moved.empty()) return;
    for (std::size_t m = 0; m < mounts.size(); ++m) {
      if (m == skip) continue;
      if (std::any_of(moved.begin(), moved.end(), [&](const model::BodyPart& part) {
            return mounts[m].fov.may_be_hidden_by(part.triangles);
          }))
        refresh(m);
    }
  }
};

RasterCoverage::RasterCoverage(const model::Rig& rig, const model::SensorLibrary& library,
                               const CoverageSettings& settings, int threads)
    : state_(std::make_unique<State>(rig, library, settings, threads)) {
  for (const model::Mount& mount : state_->rig.mounts) {
    state_->mounts.push_back(state_->place(mount));
    state_->rasters.push_back(
        detail::mount_rasters(state_->mounts.back().fov, state_->samples, state_->threads));
  }
}

RasterCoverage::~RasterCoverage() = default;
RasterCoverage::RasterCoverage(RasterCoverage&&) noexcept = default;
RasterCoverage& RasterCoverage::operator=(RasterCoverage&&) noexcept = default;

void RasterCoverage::set_mount(std::size_t index, const model::Mount& mount) {
  if (index >= state_->mounts.size()) throw std::out_of_range("RasterCoverage::set_mount");
  const model::Mount before = state_->rig.mounts[index];
  state_->rig.mounts[index] = mount;
  state_->refresh(index);
  state_->rehouse(before, mount, index);
}

void RasterCoverage::add_mount(const model::Mount& mount) {
  state_->rig.mounts.push_back(mount);
  state_->mounts.push_back(state_->place(mount));
  state_->rasters.push_back(
      detail::mount_rasters(state_->mounts.back().fov, state_->samples, state_->threads));
  state_->rehouse(std::nullopt, mount, state_->mounts.size() - 1);
}

void RasterCoverage::remove_mount(std::size_t index) {
  if (index >= state_->mounts.size()) throw std::out_of_range("RasterCoverage::remove_mount");
  const model::Mount before = state_->rig.mounts[index];
  const auto offset = static_cast<std::ptrdiff_t>(index);
  state_->rig.mounts.erase(state_->rig.mounts.begin() + offset);
  state_->mounts.erase(state_->mounts.begin() + offset);
  state_->rasters.erase(state_->rasters.begin() + offset);
  state_->rehouse(before, std::nullopt, state_->mounts.size());
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
