#pragma once
// Files the coverage subcommand writes besides the charts: the CSV table and the 3D views.
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/render/view_3d.hpp"

namespace rigdesign::cli {

/// One row per sampled angle: theta, r, SC complete and floor (exact and raster),
/// redundancy, the coarsest and noisiest covering sensors, and which sensors see it.
std::string coverage_csv(const RigCoverage& coverage);

/// The viewpoints rendered, with their file names.
std::vector<std::pair<Viewpoint, std::string>> views_3d();

/// The body and every mount's FOV volume truncated at the rig's d, one colour per mount.
void render_rig_3d(const Rig& rig, const SensorLibrary& library, Viewpoint viewpoint,
                   const std::string& path);

}  // namespace rigdesign::cli
