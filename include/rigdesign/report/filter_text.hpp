#pragma once
// `rigdesign filter`'s terminal report: per cloud a table of stages, per mount a table of loads.
#include <iosfwd>

#include "rigdesign/report/filter_report.hpp"

namespace rigdesign::report {

void print_filter_clouds(const FilterCloudsReport& report, std::ostream& out);
void print_filter_scene(const FilterSceneReport& report, std::ostream& out);

}  // namespace rigdesign::report
