#pragma once
// `rigdesign localize --json`: the same reports as the text, with every number at full
// precision, covariances and the KPIs' running statistics.
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "rigdesign/localize/accuracy_table.hpp"
#include "rigdesign/report/localize_options.hpp"
#include "rigdesign/report/localize_report.hpp"

namespace rigdesign::report {

nlohmann::json to_json(const EmitterReport& report);
nlohmann::json to_json(const GasReport& report);
nlohmann::json to_json(const ScenarioReport& report);
nlohmann::json to_json(const LogsReport& report);

/// The accuracy table (--table) with the scenario settings it ran with.
nlohmann::json accuracy_json(const std::vector<localize::AccuracyRow>& rows,
                             const LocalizeOptions& options);

}  // namespace rigdesign::report
