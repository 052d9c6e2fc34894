#include "rigdesign/filters/statistical_outlier.hpp"

#include <cmath>

#include "filters/neighbour_grid.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::filters {

model::PointCloud select_points(const model::PointCloud& cloud,
                                const std::vector<std::uint32_t>& indices) {
  model::PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  result.points.reserve(indices.size());
  for (const std::uint32_t i : indices) result.points.push_back(cloud.points[i]);
  return result;
}

std::vector<std::uint32_t> statistical_outlier_inliers(
    const model::PointCloud& cloud, const model::StatisticalOutlierParams& params) {
  if (params.neighbours <= 0) {
    throw model::InputError(model::Diagnostic{
        {}, "statistical_outlier.neighbours", "must be > 0", "a neighbour count N > 0"});
  }
  std::vector<std::uint32_t> kept;
  if (cloud.size() < 2) {
    for (std::uint32_t i = 0; i < cloud.size(); ++i) kept.push_back(i);
    return kept;
  }
  const filters::NeighbourGrid grid = params.cell > 0
                                          ? filters::NeighbourGrid(cloud.points, params.cell)
                                          : filters::grid_for(cloud.points, params.neighbours);
  std::vector<double> mean_distance(cloud.size());
  filters::NeighbourScratch scratch;
  double sum = 0.0;
  double sum_squares = 0.0;
  for (std::uint32_t rank = 0; rank < cloud.size(); ++rank) {  // in the grid's cell order
    grid.nearest(rank, params.neighbours, scratch);
    double total = 0.0;
    for (const float d2 : scratch.nearest) total += std::sqrt(static_cast<double>(d2));
    const double mean = total / static_cast<double>(scratch.nearest.size());
    mean_distance[grid.index_at(rank)] = mean;
    sum += mean;
    sum_squares += mean * mean;
  }
  // Sample standard deviation, as PCL computes it.
  const double n = static_cast<double>(cloud.size());
  const double mean = sum / n;
  const double variance = (sum_squares - sum * sum / n) / (n - 1);
  const double threshold = mean + params.std_multiplier * std::sqrt(std::max(0.0, variance));
  kept.reserve(cloud.size());
  for (std::uint32_t i = 0; i < cloud.size(); ++i) {
    if (mean_distance[i] <= threshold) kept.push_back(i);
  }
  return kept;
}

model::PointCloud statistical_outlier_removal(const model::PointCloud& cloud,
                                              const model::StatisticalOutlierParams& params) {
  return select_points(cloud, statistical_outlier_inliers(cloud, params));
}

}  // namespace rigdesign::filters
