#include "rigdesign/filters/radius_outlier.hpp"

#include <algorithm>
#include <cmath>

#include "filters/neighbour_grid.hpp"
#include "rigdesign/filters/statistical_outlier.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::filters {
namespace {

// At most this many grid cells per point: a sparse cloud over a large volume (a lidar's)
// would otherwise clear a grid of millions of empty cells on every frame.
constexpr double kRadiusGridCellsPerPoint = 4.0;

// The cell edge: the radius (a ball spans at most 3 cells a side), or larger when the cloud's
// box would hold more than kRadiusGridCellsPerPoint cells per point at that size.
double radius_grid_cell(const std::vector<model::Point3f>& points, double radius) {
  Eigen::Array3f low = points.front().array();
  Eigen::Array3f high = low;
  for (const model::Point3f& p : points) {
    low = low.min(p.array());
    high = high.max(p.array());
  }
  const Eigen::Array3d extent = (high - low).cast<double>().max(radius);
  const double volume = extent.prod();
  const double cells = kRadiusGridCellsPerPoint * static_cast<double>(points.size());
  return std::max(radius, std::cbrt(volume / cells));
}

// The largest float whose value is at most `value`: a float squared distance d is within the
// double bound exactly when d <= this (PCL compares its float distances to radius^2 in double).
float float_at_most(double value) {
  float rounded = static_cast<float>(value);
  if (static_cast<double>(rounded) > value) rounded = std::nextafter(rounded, 0.0f);
  return rounded;
}

}  // namespace

std::vector<std::uint32_t> radius_outlier_inliers(const model::PointCloud& cloud,
                                                  const model::RadiusOutlierParams& params) {
  if (!(params.radius > 0)) {
    throw model::InputError(model::Diagnostic{
        {}, "radius_outlier.radius", "must be > 0", "the search radius in metres, > 0"});
  }
  if (params.min_neighbours <= 0) {
    throw model::InputError(model::Diagnostic{
        {}, "radius_outlier.min_neighbours", "must be > 0", "a neighbour count, > 0"});
  }
  std::vector<std::uint32_t> kept;
  if (cloud.empty()) return kept;
  // Kept from call to call on each thread, as the statistical outlier removal's grid.
  thread_local NeighbourGrid this_threads_radius_grid;
  thread_local std::vector<unsigned char> this_threads_keep;
  NeighbourGrid& grid = this_threads_radius_grid;
  std::vector<unsigned char>& keep = this_threads_keep;
  grid.build(cloud.points, radius_grid_cell(cloud.points, params.radius));
  const float squared_radius = float_at_most(params.radius * params.radius);
  const auto enough = static_cast<std::size_t>(params.min_neighbours);
  keep.assign(cloud.size(), 0);
  // Queried in cell order (neighbouring queries share cells in cache), answered by index.
  const auto points = static_cast<std::uint32_t>(cloud.size());
  for (std::uint32_t rank = 0; rank < points; ++rank) {
    keep[grid.index_at(rank)] = grid.has_neighbours(rank, squared_radius, enough) ? 1 : 0;
  }
  kept.reserve(cloud.size());
  for (std::uint32_t i = 0; i < points; ++i) {
    if (keep[i] != 0) kept.push_back(i);
  }
  return kept;
}

model::PointCloud radius_outlier_removal(const model::PointCloud& cloud,
                                         const model::RadiusOutlierParams& params) {
  return select_points(cloud, radius_outlier_inliers(cloud, params));
}

}  // namespace rigdesign::filters
