#pragma once
// `rigdesign check --format github`: GitHub Actions workflow commands.
#include <string>
#include <vector>

#include "rigdesign/report/file_report.hpp"

namespace rigdesign::report {

/// An ::error annotation per invalid input and failed requirement, ::warning per warning, at
/// the rig line that causes it; then the summary line.
std::string format_github(const std::vector<FileReport>& reports);

}  // namespace rigdesign::report
