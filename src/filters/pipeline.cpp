#include "rigdesign/filters/pipeline.hpp"

#include <chrono>

namespace rigdesign {

std::optional<Pipeline> preset_pipeline(const std::string& name) {
  const StageParams voxel = VoxelGridParams{};
  const StageParams sor = StatisticalOutlierParams{};
  const StageParams floor_1 = FloorRemoval1Params{};
  const StageParams floor_2 = FloorRemoval2Params{};
  if (name == "P1") return Pipeline{name, {sor, voxel, floor_1}};
  if (name == "P2") return Pipeline{name, {voxel, sor, floor_1}};
  if (name == "P3") return Pipeline{name, {voxel, floor_1, sor}};
  if (name == "P4") return Pipeline{name, {voxel, sor, floor_2}};
  return std::nullopt;
}

PointCloud run_stage(const StageParams& stage, const PointCloud& cloud) {
  return std::visit(
      [&](const auto& params) -> PointCloud {
        using Params = std::decay_t<decltype(params)>;
        if constexpr (std::is_same_v<Params, VoxelGridParams>) return voxel_grid(cloud, params);
        if constexpr (std::is_same_v<Params, StatisticalOutlierParams>) {
          return statistical_outlier_removal(cloud, params);
        }
        if constexpr (std::is_same_v<Params, PassThroughParams>) return pass_through(cloud, params);
        if constexpr (std::is_same_v<Params, RemovePlaneParams>) {
          const PlaneFit plane = fit_plane_ransac(cloud, params.ransac);
          PointCloud rest = cloud;
          if (!plane.found) return rest;
          std::vector<bool> inlier(cloud.size(), false);
          for (const std::uint32_t i : plane.inliers) inlier[i] = true;
          rest.points.clear();
          for (std::size_t i = 0; i < cloud.size(); ++i) {
            if (!inlier[i]) rest.points.push_back(cloud.points[i]);
          }
          return rest;
        }
        if constexpr (std::is_same_v<Params, FloorRemoval1Params>)
          return remove_floor_1(cloud, params);
        if constexpr (std::is_same_v<Params, FloorRemoval2Params>)
          return remove_floor_2(cloud, params);
        if constexpr (std::is_same_v<Params, NegativeObstacleParams>) {
          return mark_negative_obstacles(cloud, params);
        }
      },
      stage);
}

PointCloud run_pipeline(const Pipeline& pipeline, const PointCloud& input,
                        std::vector<StageRun>* runs) {
  // The first stage reads the caller's cloud in place: a sensor frame is megabytes, and
  // copying it would be paid on every frame.
  const PointCloud* current = &input;
  PointCloud cloud;
  for (const StageParams& stage : pipeline.stages) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t points_in = current->size();
    cloud = run_stage(stage, *current);
    current = &cloud;
    if (runs != nullptr) {
      runs->push_back(
          {stage_name(stage), points_in, cloud.size(),
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    }
  }
  return current == &input ? input : cloud;
}

}  // namespace rigdesign
