#include "rigdesign/filters/pipeline_timing.hpp"

#include <algorithm>
#include <optional>
#include <variant>

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

FilteringLoadRate pipeline_load(const PipelineTiming& timing, const model::Pipeline& pipeline,
                                double points_per_frame, double frequency) {
  if (throttled_rate(pipeline, frequency) >= frequency) {
    return filtering_load(timing.total.median, points_per_frame, frequency);
  }
  double cores = 0.0;
  double rate = frequency;
  for (std::size_t s = 0; s < pipeline.stages.size() && s < timing.stages.size(); ++s) {
    cores += timing.stages[s].seconds.median * rate;  // a throttle itself sees every frame
    if (const auto* throttle = std::get_if<model::ThrottleParams>(&pipeline.stages[s])) {
      rate = std::min(rate, throttle->rate_hz);
    }
  }
  return {cores, points_per_frame > 0 ? cores / (points_per_frame * frequency) : 0.0};
}

FramesLoad measure_filtering_load(const model::Pipeline& pipeline,
                                  std::span<const model::PointCloud> frames, double frequency) {
  FramesLoad measured;
  measured.frames = frames.size();
  PipelineStream stream(pipeline);
  std::vector<double> passed_seconds;
  std::vector<double> dropped_seconds;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    std::vector<StageRun> runs;
    const std::optional<model::PointCloud> result =
        stream.run(frames[i], frequency > 0 ? static_cast<double>(i) / frequency : 0.0, &runs);
    measured.points += frames[i].size();
    (result ? passed_seconds : dropped_seconds).push_back(total_seconds(runs));
    if (result) measured.kept += result->size();
  }
  measured.passed = passed_seconds.size();  // at least the first frame
  measured.seconds_per_frame = spread_of(passed_seconds);
  const double count = static_cast<double>(frames.size());
  const double points_per_frame = static_cast<double>(measured.points) / count;
  // Paper 1, eq. 5, with each kind of frame at its own rate (frames x frequency / count).
  const double passed_rate = frequency * static_cast<double>(passed_seconds.size()) / count;
  const double dropped_rate = frequency * static_cast<double>(dropped_seconds.size()) / count;
  double cores = measured.seconds_per_frame.median * passed_rate;
  if (!dropped_seconds.empty()) cores += model::median(dropped_seconds) * dropped_rate;
  measured.load = {cores, points_per_frame > 0 ? cores / (points_per_frame * frequency) : 0.0};
  return measured;
}

}  // namespace rigdesign::filters
