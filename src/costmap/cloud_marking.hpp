#pragma once
// What the obstacle (2D) and voxel (3D) layers share when they take in a cloud: the cells its
// points mark, and the stretch of each ray that clears. nav2's ObstacleLayer and VoxelLayer
// apply the same rules (ObservationSource::marks, the raytrace range).
#include <optional>

#include "rigdesign/costmap/grid_traversal.hpp"
#include "rigdesign/costmap/observation.hpp"

namespace rigdesign::costmap::detail {

/// Calls `mark(cell)` with the integer cell (Dim ints) of each point of `observation` that
/// marks and falls inside the grid; `frame.to_grid` maps world points to grid coordinates.
template <int Dim, typename Frame, typename Mark>
void for_each_marked_cell(const Frame& frame, const CloudObservation& observation, Mark mark) {
  const ObservationSource& source = observation.source;
  const model::Vec3 origin = observation.T_world_cloud * observation.cloud->origin.cast<double>();
  for (const model::Point3f& point : observation.cloud->points) {
    const model::Vec3 p_world = observation.T_world_cloud * point.cast<double>();
    if (!source.marks(p_world, origin)) continue;
    const GridPoint<Dim> g = frame.to_grid(p_world);
    if (!inside_grid<Dim>(g, frame.size)) continue;
    const Eigen::Matrix<std::ptrdiff_t, Dim, 1> cell =
        g.array().floor().template cast<std::ptrdiff_t>().matrix();
    mark(cell);
  }
}

/// The stretch of the ray from `origin_world` to `p_world` that clears: from the raytrace
/// minimum range to the end point, or to the raytrace maximum range when the end point lies
/// beyond it (`cut_short`: the end cell is cleared too, nothing was seen there).
struct ClearingRay {
  model::Vec3 start;
  model::Vec3 end;
  bool cut_short = false;
};

/// Nothing when the end point lies within the raytrace minimum range.
inline std::optional<ClearingRay> clearing_ray(const model::Vec3& origin_world,
                                               const model::Vec3& p_world,
                                               const ObservationSource& source) {
  const model::Vec3 ray = p_world - origin_world;
  const double length = ray.norm();
  if (!(length > source.raytrace_min_range)) return std::nullopt;
  ClearingRay clearing;
  clearing.start = origin_world + ray * (source.raytrace_min_range / length);
  clearing.cut_short = length > source.raytrace_max_range;
  clearing.end = clearing.cut_short
                     ? model::Vec3(origin_world + ray * (source.raytrace_max_range / length))
                     : p_world;
  return clearing;
}

}  // namespace rigdesign::costmap::detail
