#include "filters/neighbour_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rigdesign::filters {
namespace {

// Cells beyond this count make the dense grid too large: the cell grows instead.
constexpr double kMaxCells = 16e6;

}  // namespace

NeighbourGrid::NeighbourGrid(const std::vector<Point3f>& points, double cell)
    : points_(points), cell_(static_cast<float>(cell)) {
  low_ = Eigen::Array3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Array3f high = -low_;
  for (const Point3f& p : points) {
    low_ = low_.min(p.array());
    high = high.max(p.array());
  }
  if (points.empty()) low_ = high = Eigen::Array3f::Zero();
  auto extent = [&] { return ((high - low_) / cell_).floor().cast<int>() + 1; };
  dims_ = extent();
  while (static_cast<double>(dims_.x()) * dims_.y() * dims_.z() > kMaxCells) {
    cell_ *= 1.5f;
    dims_ = extent();
  }
  const std::size_t cells = static_cast<std::size_t>(dims_.x()) * dims_.y() * dims_.z();
  cell_start_.assign(cells + 1, 0);
  std::vector<Eigen::Array3i> point_cell(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    point_cell[i] = ((points[i].array() - low_) / cell_).floor().cast<int>().min(dims_ - 1);
    ++cell_start_[cell_of(point_cell[i]) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) {
    occupied_ += cell_start_[c + 1] != 0 ? 1 : 0;
    cell_start_[c + 1] += cell_start_[c];
  }
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  sorted_.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    sorted_[fill[cell_of(point_cell[i])]++] = static_cast<std::uint32_t>(i);
  }
  sorted_points_.resize(points.size());
  sorted_cell_.resize(points.size());
  for (std::size_t rank = 0; rank < points.size(); ++rank) {
    sorted_points_[rank] = points[sorted_[rank]];
    sorted_cell_[rank] = point_cell[sorted_[rank]];
  }
}

std::size_t NeighbourGrid::cell_of(const Eigen::Array3i& cell) const {
  return (static_cast<std::size_t>(cell.z()) * dims_.y() + cell.y()) * dims_.x() + cell.x();
}

double NeighbourGrid::mean_occupancy() const {
  return occupied_ == 0 ? 0.0 : static_cast<double>(points_.size()) / static_cast<double>(occupied_);
}

void NeighbourGrid::nearest(std::uint32_t rank, int k, std::vector<float>& distances) const {
  distances.clear();
  const Point3f& p = sorted_points_[rank];
  const Eigen::Array3i centre = sorted_cell_[rank];
  // How far p is from the nearest face of its own cell: every point outside the cube of
  // rings 0..r is at least r * cell + this far away.
  const Eigen::Array3f cell_low = low_ + centre.cast<float>() * cell_;
  const float inset = std::min((p.array() - cell_low).minCoeff(), (cell_low + cell_ - p.array()).minCoeff());
  const int max_ring = dims_.maxCoeff();
  const auto consider = [&](std::uint32_t other) {
    if (other == rank) return;
    const float d2 = (sorted_points_[other] - p).squaredNorm();
    if (static_cast<int>(distances.size()) == k) {
      if (d2 >= distances.back()) return;
      distances.pop_back();
    }
    distances.insert(std::upper_bound(distances.begin(), distances.end(), d2), d2);
  };
  for (int ring = 0; ring <= max_ring; ++ring) {
    const Eigen::Array3i from = (centre - ring).max(0);
    const Eigen::Array3i to = (centre + ring).min(dims_ - 1);
    for (int z = from.z(); z <= to.z(); ++z) {
      const bool z_face = std::abs(z - centre.z()) == ring;
      for (int y = from.y(); y <= to.y(); ++y) {
        const bool yz_face = z_face || std::abs(y - centre.y()) == ring;
        const auto scan = [&](int x) {
          const std::size_t cell = cell_of({x, y, z});
          for (std::uint32_t s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) consider(s);
        };
        if (yz_face) {  // on a y or z face of the shell the whole row is new
          for (int x = from.x(); x <= to.x(); ++x) scan(x);
          continue;
        }
        // Inside the shell only its two x faces are new (when inside the grid).
        if (centre.x() - ring >= 0) scan(centre.x() - ring);
        if (ring > 0 && centre.x() + ring < dims_.x()) scan(centre.x() + ring);
      }
    }
    const float reach = static_cast<float>(ring) * cell_ + inset;
    if (static_cast<int>(distances.size()) == k && distances.back() <= reach * reach) return;
  }
}

double estimate_cell(const std::vector<Point3f>& points, int per_cell) {
  if (points.size() < 2) return 1.0;
  Eigen::Array3f low = points.front().array();
  Eigen::Array3f high = low;
  for (const Point3f& p : points) {
    low = low.min(p.array());
    high = high.max(p.array());
  }
  const double diagonal = std::max(1e-6, static_cast<double>((high - low).matrix().norm()));
  // Points on surfaces: spacing ~ diagonal / sqrt(n); refine once from the real occupancy.
  double cell = 2.0 * diagonal / std::sqrt(static_cast<double>(points.size()));
  const double occupancy = NeighbourGrid(points, cell).mean_occupancy();
  if (occupancy > 0) cell *= std::sqrt(per_cell / occupancy);
  return std::max(cell, diagonal * 1e-6);
}

}  // namespace rigdesign::filters
