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
/// Paper 2's filtering (section 3.2): P2_paper2 = throttle (2 Hz, the Kinect's), radius
/// outlier removal, voxel grid. Returns nothing for another name.
std::optional<model::Pipeline> preset_pipeline(const std::string& name);

/// The preset names preset_pipeline knows, in order: P1, P2, P3, P4, P2_paper2.
const std::vector<std::string>& preset_pipeline_names();

struct StageRun {
  std::string stage;
  std::size_t points_in = 0;
  std::size_t points_out = 0;
  double seconds = 0.0;
};

/// The pipeline with every stage that can use threads (statistical_outlier) set to `threads`.
model::Pipeline with_threads(model::Pipeline pipeline, int threads);

/// Runs the stages in order on one cloud; `runs` receives one entry per stage. The cloud is a
/// frame on its own: a throttle stage keeps it (the first frame of a stream always passes).
model::PointCloud run_pipeline(const model::Pipeline& pipeline, const model::PointCloud& input,
                               std::vector<StageRun>* runs = nullptr);

/// One stage, run by its entry in the stage registry (model/filter_params.hpp).
model::PointCloud run_stage(const model::StageParams& stage, const model::PointCloud& cloud);

/// A pipeline run frame after frame, as a sensor delivers them: each throttle stage keeps its
/// schedule here (model::ThrottleParams) and drops the frames between its due times.
class PipelineStream {
 public:
  explicit PipelineStream(model::Pipeline pipeline);

  /// Runs the frame taken at `stamp` [s] (stamps must not decrease). Nothing when a throttle
  /// stage dropped the frame; the stages before it ran, and `runs` lists them and the
  /// throttle (its points_out 0).
  std::optional<model::PointCloud> run(const model::PointCloud& frame, double stamp,
                                       std::vector<StageRun>* runs = nullptr);

  const model::Pipeline& pipeline() const { return pipeline_; }

 private:
  model::Pipeline pipeline_;
  std::vector<std::optional<double>> next_due_;  // per stage: a throttle's next due stamp [s]
};

/// Frames per second that pass every throttle stage of `pipeline` in the long run when the
/// sensor delivers `frequency` [Hz]: the smallest of frequency and the throttles' rates.
double throttled_rate(const model::Pipeline& pipeline, double frequency);

}  // namespace rigdesign::filters
