#pragma once
/// What the rig's pairs of mounts decide, from one covisibility of the rig (issue 38): D5
/// crosstalk between active sensors (always) and R9 calibration overlap (when the requirements
/// ask for it). Nothing is computed for a rig with fewer than two active sensors and no R9.
#include <vector>

#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/requirements.hpp"

namespace rigdesign::metrics {

struct PairFindings {
  std::vector<RequirementResult> verdicts;
  std::vector<model::Diagnostic> warnings;
};

PairFindings pair_findings(const model::Rig& rig, const model::SensorLibrary& library,
                           const model::Requirements* requirements);

}  // namespace rigdesign::metrics
