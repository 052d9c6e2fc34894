#pragma once
// Files the coverage subcommand writes besides the charts: the CSV table and the 3D views;
// `report` and `select` read the pictures back for their pages.
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/render/view_3d.hpp"
#include "rigdesign/report/html_report.hpp"

namespace rigdesign::cli {

/// One row per sampled angle: theta, r, SC complete and floor (exact and raster),
/// redundancy, the coarsest and noisiest covering sensors, and which sensors see it.
std::string coverage_csv(const metrics::RigCoverage& coverage);

/// The viewpoints rendered, with their file names.
std::vector<std::pair<render::Viewpoint, std::string>> views_3d();

/// Writes every coverage picture and table of a rig into `folder` (which must exist): SC
/// curves (PNG, SVG), cross-sections at `angles_deg`, 3D views (unless `with_3d` is false),
/// coverage.csv and coverage.json. Returns the paths written.
std::vector<std::string> write_coverage_files(const model::Rig& rig,
                                              const model::SensorLibrary& library,
                                              const metrics::RigCoverage& coverage,
                                              const std::vector<double>& angles_deg,
                                              const std::string& folder, bool with_3d);

/// The coverage pictures write_coverage_files put in `folder` (sections at `angles_deg`), read
/// back for the page, with their captions.
std::vector<report::ReportFigure> coverage_figures(const std::string& folder,
                                                   const std::vector<double>& angles_deg);

/// The body and every mount's FOV volume truncated at the rig's d, one colour per mount.
void render_rig_3d(const model::Rig& rig, const model::SensorLibrary& library,
                   render::Viewpoint viewpoint, const std::string& path);

}  // namespace rigdesign::cli
