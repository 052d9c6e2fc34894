#include "rigdesign/filters/statistical_outlier.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "filters/neighbour_grid.hpp"
#include "rigdesign/model/idle_cores.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/parallel_for.hpp"

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
  // The grid and the per-point means live from call to call on each thread: a pipeline run
  // per frame then allocates nothing here once its clouds stop growing.
  thread_local NeighbourGrid this_threads_grid;
  thread_local std::vector<double> this_threads_means;
  // Plain references: the helper threads below must reach this thread's instances, and a
  // thread_local named inside the lambda would be the helper's own.
  NeighbourGrid& grid = this_threads_grid;
  std::vector<double>& mean_distance = this_threads_means;
  if (params.cell > 0) {
    grid.build(cloud.points, params.cell);
  } else {
    build_grid_for(cloud.points, params.neighbours, grid);
  }
  mean_distance.resize(cloud.size());
  // Queries go in chunks of the cell order (neighbouring queries keep their cells in cache),
  // taken from a shared counter: a thread slowed by other work on its core takes fewer chunks,
  // so two threads on a loaded machine are not held back by the slower one. Each point's mean
  // is written by whichever thread answers it.
  constexpr std::size_t kChunk = 4096;
  // At most the threads asked for, the points allow, and cores are idle now (see idle_cores).
  std::size_t threads = std::clamp<std::size_t>(
      cloud.size() / model::kMinPointsPerFilterThread, 1,
      static_cast<std::size_t>(std::clamp(params.threads, 1, model::kMaxFilterThreads)));
  if (threads > 1) threads = std::min(threads, static_cast<std::size_t>(1 + model::idle_cores()));
  // This thread's scratch lives from call to call like the grid; the helpers get their own.
  thread_local NeighbourScratch this_threads_scratch;
  NeighbourScratch& callers_scratch = this_threads_scratch;
  std::vector<NeighbourScratch> helper_scratches(threads - 1);
  model::parallel_for_chunks(
      cloud.size(), kChunk, static_cast<int>(threads),
      [&](std::size_t from, std::size_t to, int worker) {
        NeighbourScratch& scratch =
            worker == 0 ? callers_scratch : helper_scratches[static_cast<std::size_t>(worker - 1)];
        std::vector<double>& roots = scratch.roots;
        scratch.bound = 0.0f;
        for (std::size_t rank = from; rank < to; ++rank) {
          grid.nearest(static_cast<std::uint32_t>(rank), params.neighbours, scratch);
          const std::size_t found = scratch.nearest.size();
          // The roots in one loop the compiler vectorises, then summed in order as before.
          roots.resize(found);
          for (std::size_t i = 0; i < found; ++i) {
            roots[i] = std::sqrt(static_cast<double>(scratch.nearest[i]));
          }
          double total = 0.0;
          for (const double root : roots) total += root;
          mean_distance[grid.index_at(static_cast<std::uint32_t>(rank))] =
              total / static_cast<double>(found);
        }
      });
  // Summed in input order whatever the thread count, so the threshold is the same bit for bit.
  double sum = 0.0;
  double sum_squares = 0.0;
  for (const double mean : mean_distance) {
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
