#pragma once
// `rigdesign check --format json`: per file its kind, status, diagnostics and verdicts.
#include <string>
#include <vector>

#include "rigdesign/report/file_report.hpp"

namespace rigdesign::report {

std::string format_json(const std::vector<FileReport>& reports, int exit_code);

}  // namespace rigdesign::report
