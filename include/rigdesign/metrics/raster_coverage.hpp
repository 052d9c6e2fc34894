#pragma once
/// The raster path kept mount by mount (issue 37's studio): each mount's raster of every
/// sampled cross-section is stored, so a change to one mount (its pose, sensor or mode)
/// recomputes that mount's rasters alone and the union is re-counted from the others'.
/// The numbers are compute_coverage's with `exact = false`, bit for bit.
#include <cstddef>
#include <memory>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"

namespace rigdesign::metrics {

class RasterCoverage {
 public:
  /// Copies the rig (body and mounts) and the library; every mount's references must
  /// resolve (check_rig_references). `settings.exact` is ignored. A mount's sections are
  /// rasterised on `threads` threads (the numbers do not depend on how many).
  RasterCoverage(const model::Rig& rig, const model::SensorLibrary& library,
                 const CoverageSettings& settings = {}, int threads = 1);
  ~RasterCoverage();
  RasterCoverage(RasterCoverage&&) noexcept;
  RasterCoverage& operator=(RasterCoverage&&) noexcept;

  /// Mount `index` becomes `mount`; only its rasters are recomputed.
  void set_mount(std::size_t index, const model::Mount& mount);
  void add_mount(const model::Mount& mount);
  void remove_mount(std::size_t index);
  std::size_t mount_count() const;

  /// The rig's coverage on the raster path, judged against `sectors`.
  RigCoverage coverage(const std::vector<model::SectorRequirement>& sectors) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rigdesign::metrics
