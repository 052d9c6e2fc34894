#pragma once
/// Sector verdicts of a rig after failures, on the exact path (issue 32: `select --robust`
/// verifies every failure of the chosen rig; computing a whole coverage per failure redid
/// every mount's cross-sections each time). Each mount's section polygons and floor
/// intervals are computed once per sampled angle inside some sector and every failure's
/// union reuses them; verdicts are judged as compute_coverage judges a sector (the minimum
/// over the sector's sampled angles of judged_share, compared with >=).
#include <cstddef>
#include <functional>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"

namespace rigdesign::metrics {

/// For each failure (per mount of `rig`: whether it fails), the indices of the `sectors`
/// whose thresholds the remaining mounts miss. `settings.exact` must be set. `progress`
/// hears (angles done, angles in total).
std::vector<std::vector<std::size_t>> sectors_broken_by(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings,
    const std::vector<std::vector<bool>>& failures,
    const std::function<void(double, double)>& progress = {});

}  // namespace rigdesign::metrics
