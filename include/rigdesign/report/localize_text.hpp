#pragma once
// `rigdesign localize`'s terminal report: per emitter the estimate, its uncertainty and KPIs;
// per CO2 log the detections and scores; the accuracy table over seeds; the files written.
#include <iosfwd>
#include <string>
#include <vector>

#include "rigdesign/localize/accuracy_table.hpp"
#include "rigdesign/report/localize_options.hpp"
#include "rigdesign/report/localize_report.hpp"

namespace rigdesign::report {

/// The scenario, then each emitter report.
void print_scenario(const ScenarioReport& report, const LocalizeOptions& options,
                    std::ostream& out);

/// An RSSI log with its emitter reports, or a CO2 log's detections.
void print_log(const LogReport& report, const LocalizeOptions& options, std::ostream& out);

/// The accuracy over seeds, one row per scenario and method (--table).
void print_accuracy(const std::vector<localize::AccuracyRow>& rows, const LocalizeOptions& options,
                    std::ostream& out);

/// "  wrote FILE", a line per file.
void print_written(const std::vector<std::string>& files, std::ostream& out);

}  // namespace rigdesign::report
