#pragma once
// `rigdesign check`'s text format: per file its summary, problems and verdicts, then a count.
#include <string>
#include <vector>

#include "rigdesign/report/file_report.hpp"

namespace rigdesign::report {

/// "check: 3 file(s), 0 invalid; requirements: 7 pass, 1 fail, 0 not evaluated\n".
std::string check_summary(const std::vector<FileReport>& reports);

std::string format_text(const std::vector<FileReport>& reports);

}  // namespace rigdesign::report
