#pragma once
// `select --json`: every relaxation step with its search, cost, rig, refinement and coverage,
// the binding requirements and the files written.
#include <nlohmann/json_fwd.hpp>

#include "rigdesign/report/select_report.hpp"

namespace rigdesign::report {

/// Needs `report.outcome`.
nlohmann::json to_json(const SelectReport& report);

}  // namespace rigdesign::report
