#pragma once
// `select`'s terminal report: the inputs, each relaxation step as the loop finishes it, then
// the trace table and the chosen rig (or, with the policy exhausted, what binds).
#include <cstddef>
#include <iosfwd>

#include "rigdesign/report/select_report.hpp"

namespace rigdesign::report {

/// Catalog, requirements, budget and policy.
void print_select_header(const SelectReport& report, std::ostream& out);

/// Step `index` of the loop: what it asked, the cheapest rig and the search's effort.
void print_select_iteration(const SelectReport& report, std::size_t index,
                            const select::RelaxationIteration& iteration, std::ostream& out);

/// The trace table and the verdict; needs `report.outcome`.
void print_select_summary(const SelectReport& report, std::ostream& out);

}  // namespace rigdesign::report
