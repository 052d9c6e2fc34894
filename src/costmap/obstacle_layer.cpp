#include "rigdesign/costmap/obstacle_layer.hpp"

#include "cloud_marking.hpp"
#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {
namespace {

using detail::GridPoint;
using detail::GridSize;
using detail::GridStride;

struct PlaneFrame {
  model::Vec2 corner;
  double inverse_resolution;
  GridSize<2> size;
  GridStride<2> stride;

  explicit PlaneFrame(const GridWindow& w)
      : corner(w.origin()),
        inverse_resolution(1.0 / w.resolution),
        size(w.width, w.height),
        stride(1, w.width) {}
  GridPoint<2> to_grid(const model::Vec3& p_world) const {
    return (p_world.head<2>() - corner) * inverse_resolution;
  }
};

void clear_cloud(const PlaneFrame& frame, std::uint8_t* cells,
                 const CloudObservation& observation) {
  const ObservationSource& source = observation.source;
  const model::Vec3 origin = observation.T_world_cloud * observation.cloud->origin.cast<double>();
  for (const model::Point3f& point : observation.cloud->points) {
    const model::Vec3 p_world = observation.T_world_cloud * point.cast<double>();
    if (!source.in_height_band(p_world.z())) continue;
    const auto clearing = detail::clearing_ray(origin, p_world, source);
    if (!clearing) continue;
    const bool cut_short = clearing->cut_short;
    GridPoint<2> a = frame.to_grid(clearing->start);
    GridPoint<2> b = frame.to_grid(clearing->end);
    bool end_clipped = false;
    if (!detail::clip_to_grid<2>(a, b, frame.size, end_clipped)) continue;
    const bool include_end = cut_short || end_clipped || !detail::inside_grid<2>(b, frame.size);
    detail::walk_cells<2>(a, b, frame.size, frame.stride, include_end,
                          [cells](std::ptrdiff_t index) { cells[index] = cost::kFree; });
  }
}

void mark_cloud(const PlaneFrame& frame, std::uint8_t* cells, const CloudObservation& observation) {
  detail::for_each_marked_cell<2>(frame, observation, [&](const auto& cell) {
    cells[cell.x() + cell.y() * frame.stride.y()] = cost::kLethal;
  });
}

}  // namespace

ObstacleLayer::ObstacleLayer(const GridWindow& window, const ObstacleLayerParams& params)
    : grid_(window, params.track_unknown_space ? cost::kUnknown : cost::kFree) {}

void ObstacleLayer::update(std::span<const CloudObservation> observations) {
  const PlaneFrame frame(grid_.window());
  std::uint8_t* cells = grid_.cells().data();
  // Every clearing before any marking, as nav2's ObstacleLayer::updateBounds does.
  for (const CloudObservation& observation : observations) {
    if (observation.cloud != nullptr && observation.source.clearing)
      clear_cloud(frame, cells, observation);
  }
  for (const CloudObservation& observation : observations) {
    if (observation.cloud != nullptr && observation.source.marking)
      mark_cloud(frame, cells, observation);
  }
}

}  // namespace rigdesign::costmap
