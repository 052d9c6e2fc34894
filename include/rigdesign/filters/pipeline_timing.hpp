#pragma once
/// Timing a filter pipeline, and paper 1's filtering load U_f (section 3, eq. 5): the time a
/// sensor's frames take through the pipeline, times the sensor's frame rate, in
/// core-equivalents of the machine that ran it (one thread). Times are wall-clock, so only
/// the point counts are deterministic.
#include <span>
#include <string>
#include <vector>

#include "rigdesign/filters/pipeline.hpp"

namespace rigdesign::filters {

/// Repeated runs' times [s]: model::median and the 95th model::percentile.
struct TimeSpread {
  double median = 0.0;
  double p95 = 0.0;
};

struct StageTiming {
  std::string stage;
  std::size_t points_in = 0;  ///< of the first run (every run gives the same)
  std::size_t points_out = 0;
  TimeSpread seconds;
};

struct PipelineTiming {
  std::vector<StageTiming> stages;
  TimeSpread total;  ///< per run, the stages' times added
  model::PointCloud result;
};

/// Runs `pipeline` on `cloud` `repeat` times (>= 1).
PipelineTiming time_pipeline(const model::Pipeline& pipeline, const model::PointCloud& cloud,
                             int repeat);

/// U_f of one sensor, paper 1 eq. 5.
struct FilteringLoadRate {
  double cores = 0.0;              ///< median seconds per frame x frames per second
  double seconds_per_point = 0.0;  ///< [core-s] per delivered point: what a catalog scales
};
FilteringLoadRate filtering_load(double median_seconds_per_frame, double points_per_frame,
                                 double frequency);

/// U_f of a pipeline timed on one cloud (time_pipeline) for a sensor delivering `frequency`
/// [Hz]: each stage's median time at the rate of the frames it sees, the sensor's before the
/// first throttle stage and the throttled rate (throttled_rate) after it. Without a throttle
/// stage, filtering_load(timing.total.median, ...), unchanged.
FilteringLoadRate pipeline_load(const PipelineTiming& timing, const model::Pipeline& pipeline,
                                double points_per_frame, double frequency);

/// One sensor's simulated frames, each once through the pipeline.
struct FramesLoad {
  std::size_t frames = 0;
  std::size_t passed = 0;        ///< frames no throttle stage dropped (all without a throttle)
  std::size_t points = 0;        ///< delivered, all frames
  std::size_t kept = 0;          ///< left after the pipeline, all frames
  TimeSpread seconds_per_frame;  ///< over the frames that passed
  /// Median time of the passed frames x their rate, plus the dropped frames' median (the
  /// stages before the throttle) x theirs.
  FilteringLoadRate load;
};
/// `frames` must not be empty; `frequency` [Hz] is the sensor mode's frame rate: frame i is
/// taken at i / frequency and the frames run as one stream (PipelineStream), so throttle
/// stages keep their share.
FramesLoad measure_filtering_load(const model::Pipeline& pipeline,
                                  std::span<const model::PointCloud> frames, double frequency);

}  // namespace rigdesign::filters
