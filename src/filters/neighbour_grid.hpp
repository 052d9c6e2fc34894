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
  std::vector<float> distances;  ///< squared, every candidate of the current query (capacity)
  std::vector<float> nearest;    ///< squared, the answer's k smallest (unordered)
  float bound = 0.0f;            ///< squared distance: the previous answer's k-th, widened
};

class NeighbourGrid {
 public:
  /// `cell` > 0 [m].
  NeighbourGrid(const std::vector<model::Point3f>& points, double cell);

  /// The squared distances to the k nearest other points of the point at position `rank` of
  /// the grid's cell order, unordered, in `scratch.nearest` (fewer when the cloud has fewer
  /// points). Visiting points in cell order keeps neighbouring cells in cache and the carried
  /// radius tight.
  void nearest(std::uint32_t rank, int k, NeighbourScratch& scratch) const;

  /// The input index of the point at position `rank` of the cell order.
  std::uint32_t index_at(std::uint32_t rank) const { return sorted_[rank]; }

  /// Mean number of points in an occupied cell.
  double mean_occupancy() const;

 private:
  std::size_t cell_of(const Eigen::Array3i& cell) const;
  /// Writes the squared distances from p to every point ranked [begin, end) at out[size...],
  /// growing `out` when needed; returns the new size.
  std::size_t append_distances(const model::Point3f& p, std::uint32_t begin, std::uint32_t end,
                               std::vector<float>& out, std::size_t size) const;

  float cell_;
  Eigen::Array3f low_;
  Eigen::Array3i dims_;
  std::vector<std::uint32_t> cell_start_;  // prefix sums, size cells + 1
  std::vector<std::uint32_t> sorted_;      // point indices grouped by cell
  std::vector<float> x_, y_, z_;           // the points in that order, one array per axis
  std::vector<Eigen::Array3i> sorted_cell_;
  std::size_t occupied_ = 0;
};

/// A grid whose occupied cells hold about `per_cell` points (surfaces assumed).
NeighbourGrid grid_for(const std::vector<model::Point3f>& points, int per_cell);

}  // namespace rigdesign::filters
