#pragma once
// `occupancy --sweep`: paper 3's sweeps run side by side with its reported numbers, the trends
// it states checked on both, and each mapper's speed and memory in the same run.
#include <nlohmann/json.hpp>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/occupancy/paper3_statements.hpp"

namespace rigdesign::report {

/// The sweeps `--sweep` names ("paper3" for all of them), in paper 3's table order, each once.
std::vector<occupancy::Paper3Sweep> paper3_sweeps_named(std::span<const std::string> names,
                                                        const occupancy::Paper3Common& common);

/// A table per sweep (paper 3's P R F1 F2 F3 beside ours, trail, update time, insert rate,
/// memory), the additional rows (`extra`: our mappers), and the trends.
void print_paper3_report(std::span<const occupancy::Paper3Sweep> sweeps,
                         std::span<const occupancy::OccupancyRun> runs,
                         std::span<const std::string> extra, std::ostream& out);

/// P, R, F1, F2, F3 as JSON, an undefined score (NaN) as null: `occupancy`'s report and the
/// sweep tables write scores the same way.
nlohmann::json scores_json(const occupancy::Scores& scores);

nlohmann::json paper3_report_json(std::span<const occupancy::Paper3Sweep> sweeps,
                                  std::span<const occupancy::OccupancyRun> runs);

}  // namespace rigdesign::report
