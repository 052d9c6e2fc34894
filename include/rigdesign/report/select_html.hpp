#pragma once
// The selection's section of the chosen rig's report page: the relaxation trace, the cost
// breakdown and the Pareto plot, as HTML for html_report's ReportSection.
#include <string>

#include "rigdesign/report/select_report.hpp"

namespace rigdesign::report {

/// `pick` is the iteration whose rig the page shows; `pareto_svg` the plot's SVG document.
/// Needs `report.outcome`.
std::string selection_trace_html(const SelectReport& report,
                                 const select::RelaxationIteration& pick,
                                 const std::string& pareto_svg);

}  // namespace rigdesign::report
