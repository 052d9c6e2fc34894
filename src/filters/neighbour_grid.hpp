#pragma once
// A uniform grid over a cloud, points bucketed by cell (counting sort), for exact k-nearest
// neighbour queries. Private to filters.
//
// Why it beats a k-d tree on filter clouds: points sorted by cell put each row of cells
// (consecutive x) in one contiguous run of structure-of-arrays coordinates whose distances
// vectorise. A query is a ball search whose radius is carried over from the previous query
// (neighbours in cell order have alike spacing), widened a little: each row is trimmed to the
// ball's chord, and if the ball holds k points the k nearest are among them (exact); if not,
// the radius doubles.
#include <cstdint>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

/// Reusable buffers of one thread's queries, and the bound carried from query to query.
struct NeighbourScratch {
  std::vector<float> distances;  ///< the k-selection's scratch (capacity)
  std::vector<float> nearest;    ///< squared, the answer's k smallest (unordered)
  std::vector<double> roots;     ///< the caller's: square roots of `nearest`
  float bound = 0.0f;            ///< squared distance: the previous answer's k-th, widened
};

class NeighbourGrid {
 public:
  /// Builds the grid over `points` in cells of `cell` > 0 [m], reusing this grid's memory (a filter
  /// run per frame allocates nothing once its clouds stop growing).
  void build(const std::vector<model::Point3f>& points, double cell);

  /// The squared distances to the k nearest other points of the point at position `rank` of
  /// the grid's cell order, unordered, in `scratch.nearest` (fewer when the cloud has fewer
  /// points). Visiting points in cell order keeps neighbouring cells in cache and the carried
  /// radius tight.
  void nearest(std::uint32_t rank, int k, NeighbourScratch& scratch) const;

  /// Whether at least `enough` other points lie within squared distance `squared_radius`
  /// (inclusive) of the point at position `rank` of the cell order. Counts row by row, the
  /// query's own row first, and stops as soon as `enough` are found.
  bool has_neighbours(std::uint32_t rank, float squared_radius, std::size_t enough) const;

  /// The input index of the point at position `rank` of the cell order.
  std::uint32_t index_at(std::uint32_t rank) const { return sorted_[rank]; }

  /// Mean number of points in an occupied cell.
  double mean_occupancy() const;

 private:
  /// The cell holding `position`, clamped to the grid.
  Eigen::Array3i cell_index(const Eigen::Array3f& position) const;
  std::size_t cell_of(const Eigen::Array3i& cell) const;
  /// Writes to `out` (grown when needed) the squared distances below `bound` from the point
  /// ranked `rank` to every other point in the cells a ball of `radius` around it touches;
  /// returns how many.
  std::size_t gather_below(std::uint32_t rank, float radius, float bound,
                           std::vector<float>& out) const;

  float cell_ = 1.0f;
  float inverse_cell_ = 1.0f;  // cell indices are taken by this one product, everywhere
  Eigen::Array3f low_ = Eigen::Array3f::Zero();
  Eigen::Array3i dims_ = Eigen::Array3i::Ones();
  std::vector<std::uint32_t> cell_start_;        // prefix sums, size cells + 1
  std::vector<std::uint32_t> sorted_;            // point indices grouped by cell
  std::vector<float> x_, y_, z_;                 // the points in that order, one array per axis
  std::vector<std::uint32_t> point_cell_index_;  // build's scratch, kept for reuse
  std::size_t occupied_ = 0;
};

/// Builds `grid` so its occupied cells hold about `per_cell` points (surfaces assumed).
void build_grid_for(const std::vector<model::Point3f>& points, int per_cell, NeighbourGrid& grid);

}  // namespace rigdesign::filters
