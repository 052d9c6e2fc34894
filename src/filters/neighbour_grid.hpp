#pragma once
// A uniform grid over a cloud, points bucketed by cell (counting sort), for exact k-nearest
// neighbour queries that search rings of cells outward and stop once no closer point can
// exist. Private to filters.
#include <cstdint>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

class NeighbourGrid {
 public:
  /// `cell` > 0 [m].
  NeighbourGrid(const std::vector<Point3f>& points, double cell);

  /// Squared distances to the k nearest other points of the point at position `rank` of the
  /// grid's cell order, ascending, written to `distances` (fewer when the cloud has fewer
  /// points). Visiting points in cell order keeps neighbouring cells in cache.
  void nearest(std::uint32_t rank, int k, std::vector<float>& distances) const;

  /// The input index of the point at position `rank` of the cell order.
  std::uint32_t index_at(std::uint32_t rank) const { return sorted_[rank]; }

  /// Mean number of points in an occupied cell.
  double mean_occupancy() const;

 private:
  std::size_t cell_of(const Eigen::Array3i& cell) const;

  const std::vector<Point3f>& points_;
  float cell_;
  Eigen::Array3f low_;
  Eigen::Array3i dims_;
  std::vector<std::uint32_t> cell_start_;  // prefix sums, size cells + 1
  std::vector<std::uint32_t> sorted_;      // point indices grouped by cell
  std::vector<Point3f> sorted_points_;     // the points in that order, contiguous
  std::vector<Eigen::Array3i> sorted_cell_;
  std::size_t occupied_ = 0;
};

/// A cell size giving about `per_cell` points per occupied cell (surfaces assumed).
double estimate_cell(const std::vector<Point3f>& points, int per_cell);

}  // namespace rigdesign::filters
