#pragma once
/// R2 judged over the mounts' tolerance boxes (issue 38, item 1): one verdict per sector that
/// `check`, `metrics` and `report` list after the nominal ones, pointing at the tolerance line
/// of the mount whose error breaks the sector most.
#include <string>
#include <vector>

#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"

namespace rigdesign::metrics {

std::vector<RequirementResult> tolerance_verdicts(const model::Rig& rig,
                                                  const std::vector<SectorTolerance>& sectors);

/// "x +5 mm, pitch -1 deg": the axes of an error that are not zero ("nominal" for none).
std::string error_text(const PoseError& error);

}  // namespace rigdesign::metrics
