#pragma once
/// Swept coverage seen from above (issue 38, item 4), PNG or SVG by the file's extension.
#include <string>

#include "rigdesign/metrics/swept_coverage.hpp"

namespace rigdesign::render {

/// The cells of `run` (one of `sweep.runs`) in the world frame (the robot frame at t = 0),
/// forward (x) up and left (y) to the left, as the polar SC chart: each cell coloured by the
/// time it is first seen over [0, horizon], never-seen cells grey, the swept path's cells
/// dotted and its late cells framed in red; the body's outline at t = 0 (filled) and at the
/// horizon's end (dashed), the path of the robot's centre, axes in metres and a legend.
void plot_swept_coverage(const metrics::SweptCoverage& sweep, const metrics::SweepRun& run,
                         const std::string& title, const std::string& path, int map_size = 760);

}  // namespace rigdesign::render
