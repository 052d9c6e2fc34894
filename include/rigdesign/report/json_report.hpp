#pragma once
// JSON forms of the library's results, shared by `metrics --json` and `check --format json`.
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "rigdesign/io/config/rig_inputs.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::report {

nlohmann::json to_json(const model::Diagnostic& diagnostic);
nlohmann::json to_json(const metrics::RequirementResult& result);
nlohmann::json to_json(const io::RigInputs& inputs, const metrics::ResultantMetrics& metrics);
/// SC summaries, sectors and the N-1 table; with `curves`, every angle's values too.
nlohmann::json to_json(const metrics::RigCoverage& coverage, bool curves);

}  // namespace rigdesign::report
