#include "rigdesign/filters/pipeline.hpp"

#include <chrono>

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
  return std::nullopt;
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
  // The first stage reads the caller's cloud in place: a sensor frame is megabytes, and
  // copying it would be paid on every frame.
  const model::PointCloud* current = &input;
  model::PointCloud cloud;
  for (const model::StageParams& stage : pipeline.stages) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t points_in = current->size();
    cloud = run_stage(stage, *current);
    current = &cloud;
    if (runs != nullptr) {
      runs->push_back(
          {model::stage_name(stage), points_in, cloud.size(),
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    }
  }
  return current == &input ? input : cloud;
}

}  // namespace rigdesign::filters
