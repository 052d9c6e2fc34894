#include "rigdesign/filters/pipeline_timing.hpp"

#include "rigdesign/model/statistics.hpp"

namespace rigdesign::filters {
namespace {

constexpr double kTailShare = 0.95;  // the "p95" every timing report prints

TimeSpread spread_of(const std::vector<double>& seconds) {
  return {model::median(seconds), model::percentile(seconds, kTailShare)};
}

double total_seconds(const std::vector<StageRun>& runs) {
  double total = 0.0;
  for (const StageRun& run : runs) total += run.seconds;
  return total;
}

}  // namespace

PipelineTiming time_pipeline(const model::Pipeline& pipeline, const model::PointCloud& cloud,
                             int repeat) {
  PipelineTiming timing;
  std::vector<std::vector<double>> stage_seconds(pipeline.stages.size());
  std::vector<double> totals;
  std::vector<StageRun> first;
  for (int run = 0; run < repeat; ++run) {
    std::vector<StageRun> runs;
    timing.result = run_pipeline(pipeline, cloud, &runs);
    for (std::size_t s = 0; s < runs.size(); ++s) stage_seconds[s].push_back(runs[s].seconds);
    totals.push_back(total_seconds(runs));
    if (run == 0) first = runs;
  }
  for (std::size_t s = 0; s < first.size(); ++s) {
    timing.stages.push_back(
        {first[s].stage, first[s].points_in, first[s].points_out, spread_of(stage_seconds[s])});
  }
  timing.total = spread_of(totals);
  return timing;
}

FilteringLoadRate filtering_load(double median_seconds_per_frame, double points_per_frame,
                                 double frequency) {
  return {median_seconds_per_frame * frequency,
          points_per_frame > 0 ? median_seconds_per_frame / points_per_frame : 0.0};
}

FramesLoad measure_filtering_load(const model::Pipeline& pipeline,
                                  std::span<const model::PointCloud> frames, double frequency) {
  FramesLoad measured;
  measured.frames = frames.size();
  std::vector<double> seconds;
  for (const model::PointCloud& cloud : frames) {
    std::vector<StageRun> runs;
    measured.kept += run_pipeline(pipeline, cloud, &runs).size();
    measured.points += cloud.size();
    seconds.push_back(total_seconds(runs));
  }
  measured.seconds_per_frame = spread_of(seconds);
  measured.load = filtering_load(
      measured.seconds_per_frame.median,
      static_cast<double>(measured.points) / static_cast<double>(frames.size()), frequency);
  return measured;
}

}  // namespace rigdesign::filters
