#pragma once
// A requirement verdict in words, as `check`'s text, JUnit and GitHub formats and the report
// page state it.
#include <string>

#include "rigdesign/metrics/requirement_check.hpp"

namespace rigdesign::report {

/// "F = 10 Hz, required >= 20 Hz, margin -10 Hz (-50 %)", or "" without a measured value.
std::string measured_text(const metrics::RequirementResult& result);

/// "rig.yaml:12:5: field: fail: R1 title: measured...; explanation [set by a, b]".
std::string result_line(const metrics::RequirementResult& result);

}  // namespace rigdesign::report
