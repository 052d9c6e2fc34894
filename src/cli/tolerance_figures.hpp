#pragma once
// The pictures of a rig's mounting tolerance (issue 38): per mount with a pitch or yaw
// tolerance, the smallest SC margin over the requirement sectors against that error, the
// tolerance marked. `report` embeds them; `coverage` writes them with its charts.
#include <string>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/report/html_report.hpp"

namespace rigdesign::cli {

/// Writes tolerance_<mount>_<pitch|yaw>.png and .svg into `folder` (which must exist) and
/// returns them as figures (the SVG text), the paths appended to `written` when given.
/// Nothing without sectors or such tolerances.
std::vector<report::ReportFigure> write_tolerance_figures(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const metrics::CoverageSettings& settings,
    const std::string& folder, std::vector<std::string>* written = nullptr);

}  // namespace rigdesign::cli
