#pragma once
// `rigdesign check --format junit`: JUnit XML as Jenkins, GitLab and GitHub test reporters read
// it.
#include <string>
#include <vector>

#include "rigdesign/report/file_report.hpp"

namespace rigdesign::report {

/// One <testsuite> per file, with a <testcase> for the file's validity and one per
/// requirement: file, line, time, and the measured value, requirement and margin in
/// system-out.
std::string format_junit(const std::vector<FileReport>& reports);

}  // namespace rigdesign::report
