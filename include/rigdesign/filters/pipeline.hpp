#pragma once
/// Filter pipelines: named stages, each with its own parameters, run in order and timed
/// (paper 1, section 3, Fig. 3). A pipeline is pure data: presets P1-P4, or YAML.
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rigdesign/filters/floor_removal.hpp"
#include "rigdesign/filters/statistical_outlier.hpp"

namespace rigdesign::filters {

/// Paper 1's four pipelines, read from its text (Fig. 3): noise removal (SOR), size
/// reduction (voxel grid) and floor removal in different orders, the fourth with floor
/// removal 2. P1 = SOR, voxel grid, floor removal 1 (noise removal on the raw cloud);
/// P2 = voxel grid, SOR, floor removal 1; P3 = voxel grid, floor removal 1, SOR (SOR on the
/// fewest points); P4 = voxel grid, SOR, floor removal 2. Paper defaults in every stage.
/// Returns nothing for another name.
std::optional<model::Pipeline> preset_pipeline(const std::string& name);

struct StageRun {
  std::string stage;
  std::size_t points_in = 0;
  std::size_t points_out = 0;
  double seconds = 0.0;
};

/// The pipeline with every stage that can use threads (statistical_outlier) set to `threads`.
model::Pipeline with_threads(model::Pipeline pipeline, int threads);

/// Runs the stages in order; `runs` receives one entry per stage.
model::PointCloud run_pipeline(const model::Pipeline& pipeline, const model::PointCloud& input,
                               std::vector<StageRun>* runs = nullptr);

/// One stage, run by its entry in the stage registry (model/filter_params.hpp).
model::PointCloud run_stage(const model::StageParams& stage, const model::PointCloud& cloud);

}  // namespace rigdesign::filters
