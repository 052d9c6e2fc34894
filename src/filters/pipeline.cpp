#include "rigdesign/filters/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <utility>

#include "rigdesign/filters/radius_outlier.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::filters {
namespace {

// The RANSAC plane's inliers removed, whatever its tilt.
model::PointCloud remove_plane(const model::PointCloud& cloud,
                               const model::RemovePlaneParams& params) {
  const PlaneFit plane = fit_plane_ransac(cloud, params.ransac);
  model::PointCloud rest = cloud;
  if (!plane.found) return rest;
  std::vector<bool> inlier(cloud.size(), false);
  for (const std::uint32_t i : plane.inliers) inlier[i] = true;
  rest.points.clear();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!inlier[i]) rest.points.push_back(cloud.points[i]);
  }
  return rest;
}

// The stage registry's run functions, one per alternative of model::StageParams: a stage
// without one fails to compile in run_stage.
model::PointCloud run(const model::VoxelGridParams& params, const model::PointCloud& cloud) {
  return voxel_grid(cloud, params);
}
model::PointCloud run(const model::StatisticalOutlierParams& params,
                      const model::PointCloud& cloud) {
  return statistical_outlier_removal(cloud, params);
}
model::PointCloud run(const model::PassThroughParams& params, const model::PointCloud& cloud) {
  return pass_through(cloud, params);
}
model::PointCloud run(const model::RemovePlaneParams& params, const model::PointCloud& cloud) {
  return remove_plane(cloud, params);
}
model::PointCloud run(const model::FloorRemoval1Params& params, const model::PointCloud& cloud) {
  return remove_floor_1(cloud, params);
}
model::PointCloud run(const model::FloorRemoval2Params& params, const model::PointCloud& cloud) {
  return remove_floor_2(cloud, params);
}
model::PointCloud run(const model::NegativeObstacleParams& params, const model::PointCloud& cloud) {
  return mark_negative_obstacles(cloud, params);
}
// A lone cloud is the first frame of its stream: kept. Streams decide in PipelineStream.
model::PointCloud run(const model::ThrottleParams&, const model::PointCloud& cloud) {
  return cloud;
}
model::PointCloud run(const model::RadiusOutlierParams& params, const model::PointCloud& cloud) {
  return radius_outlier_removal(cloud, params);
}

// Whether a throttle whose next due stamp is `next_due` keeps the frame at `stamp`; moves
// `next_due` to the first multiple of the period (counted from the first kept frame) after a
// kept frame. A tolerance of a millionth of the period absorbs the rounding of stamps taken
// as i / frequency, so a 30 Hz stream throttled to 2 Hz keeps exactly every 15th frame.
bool throttle_keeps(std::optional<double>& next_due, double stamp, double rate_hz) {
  if (!(rate_hz > 0)) {
    throw model::InputError(
        model::Diagnostic{{}, "throttle.rate_hz", "must be > 0", "a frame rate in Hz, > 0"});
  }
  const double period = 1.0 / rate_hz;
  const double tolerance = 1e-6 * period;
  if (!next_due) {
    next_due = stamp + period;
    return true;
  }
  if (stamp + tolerance < *next_due) return false;
  *next_due += period * (std::floor((stamp + tolerance - *next_due) / period) + 1.0);
  return true;
}

// The stages in order, throttles asking `keep_frame` (with the stage's index); nothing once a
// throttle drops the frame. The first stage reads the caller's cloud in place: a sensor
// frame is megabytes, and copying it would be paid on every frame (a throttle copies nothing).
std::optional<model::PointCloud> run_stages(
    const model::Pipeline& pipeline, const model::PointCloud& input, std::vector<StageRun>* runs,
    const std::function<bool(std::size_t, const model::ThrottleParams&)>& keep_frame) {
  const model::PointCloud* current = &input;
  model::PointCloud cloud;
  for (std::size_t s = 0; s < pipeline.stages.size(); ++s) {
    const model::StageParams& stage = pipeline.stages[s];
    const auto start = std::chrono::steady_clock::now();
    const std::size_t points_in = current->size();
    bool dropped = false;
    if (const auto* throttle = std::get_if<model::ThrottleParams>(&stage)) {
      dropped = !keep_frame(s, *throttle);
    } else {
      cloud = run_stage(stage, *current);
      current = &cloud;
    }
    if (runs != nullptr) {
      runs->push_back(
          {model::stage_name(stage), points_in, dropped ? 0 : current->size(),
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    }
    if (dropped) return std::nullopt;
  }
  return current == &input ? input : cloud;
}

}  // namespace

std::optional<model::Pipeline> preset_pipeline(const std::string& name) {
  const model::StageParams voxel = model::VoxelGridParams{};
  const model::StageParams sor = model::StatisticalOutlierParams{};
  const model::StageParams floor_1 = model::FloorRemoval1Params{};
  const model::StageParams floor_2 = model::FloorRemoval2Params{};
  if (name == "P1") return model::Pipeline{name, {sor, voxel, floor_1}};
  if (name == "P2") return model::Pipeline{name, {voxel, sor, floor_1}};
  if (name == "P3") return model::Pipeline{name, {voxel, floor_1, sor}};
  if (name == "P4") return model::Pipeline{name, {voxel, sor, floor_2}};
  if (name == "P2_paper2") {
    return model::Pipeline{
        name, {model::ThrottleParams{}, model::RadiusOutlierParams{}, model::VoxelGridParams{}}};
  }
  return std::nullopt;
}

const std::vector<std::string>& preset_pipeline_names() {
  static const std::vector<std::string> names{"P1", "P2", "P3", "P4", "P2_paper2"};
  return names;
}

model::Pipeline with_threads(model::Pipeline pipeline, int threads) {
  for (model::StageParams& stage : pipeline.stages) {
    if (auto* sor = std::get_if<model::StatisticalOutlierParams>(&stage)) sor->threads = threads;
  }
  return pipeline;
}

model::PointCloud run_stage(const model::StageParams& stage, const model::PointCloud& cloud) {
  return std::visit([&](const auto& params) { return run(params, cloud); }, stage);
}

model::PointCloud run_pipeline(const model::Pipeline& pipeline, const model::PointCloud& input,
                               std::vector<StageRun>* runs) {
  return *run_stages(pipeline, input, runs,
                     [](std::size_t, const model::ThrottleParams&) { return true; });
}

PipelineStream::PipelineStream(model::Pipeline pipeline)
    : pipeline_(std::move(pipeline)), next_due_(pipeline_.stages.size()) {}

std::optional<model::PointCloud> PipelineStream::run(const model::PointCloud& frame, double stamp,
                                                     std::vector<StageRun>* runs) {
  return run_stages(pipeline_, frame, runs,
                    [&](std::size_t stage, const model::ThrottleParams& throttle) {
                      return throttle_keeps(next_due_[stage], stamp, throttle.rate_hz);
                    });
}

double throttled_rate(const model::Pipeline& pipeline, double frequency) {
  double rate = frequency;
  for (const model::StageParams& stage : pipeline.stages) {
    if (const auto* throttle = std::get_if<model::ThrottleParams>(&stage))
      rate = std::min(rate, throttle->rate_hz);
  }
  return rate;
}

}  // namespace rigdesign::filters
