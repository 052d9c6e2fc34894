#include "filters/neighbour_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rigdesign::filters {
namespace {

// Cells beyond this count make the dense grid too large: the cell grows instead.
constexpr double kMaxCells = 16e6;
// The next query's pre-filter: the previous k-th squared distance times this. Wide enough that
// a neighbour in cell order almost always has k survivors, narrow enough that few survive.
constexpr float kBoundWidening = 1.6f;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// The k smallest of values[0, n) moved to the front (unordered); returns the k-th.
float select_smallest(float* values, std::size_t n, std::size_t k) {
  std::nth_element(values, values + (k - 1), values + n);
  return values[k - 1];
}

}  // namespace

NeighbourGrid::NeighbourGrid(const std::vector<Point3f>& points, double cell)
    : cell_(static_cast<float>(cell)) {
  low_ = Eigen::Array3f::Constant(kInfinity);
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
  std::vector<std::uint32_t> point_cell_index(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    point_cell[i] = ((points[i].array() - low_) / cell_).floor().cast<int>().min(dims_ - 1);
    point_cell_index[i] = static_cast<std::uint32_t>(cell_of(point_cell[i]));
    ++cell_start_[point_cell_index[i] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) {
    occupied_ += cell_start_[c + 1] != 0 ? 1 : 0;
    cell_start_[c + 1] += cell_start_[c];
  }
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  sorted_.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    sorted_[fill[point_cell_index[i]]++] = static_cast<std::uint32_t>(i);
  }
  x_.resize(points.size());
  y_.resize(points.size());
  z_.resize(points.size());
  sorted_cell_.resize(points.size());
  for (std::size_t rank = 0; rank < points.size(); ++rank) {
    const Point3f& p = points[sorted_[rank]];
    x_[rank] = p.x();
    y_[rank] = p.y();
    z_[rank] = p.z();
    sorted_cell_[rank] = point_cell[sorted_[rank]];
  }
}

std::size_t NeighbourGrid::cell_of(const Eigen::Array3i& cell) const {
  return (static_cast<std::size_t>(cell.z()) * dims_.y() + cell.y()) * dims_.x() + cell.x();
}

double NeighbourGrid::mean_occupancy() const {
  return occupied_ == 0 ? 0.0 : static_cast<double>(sorted_.size()) / static_cast<double>(occupied_);
}

void NeighbourGrid::append_distances(const Point3f& p, std::uint32_t begin, std::uint32_t end,
                                     std::vector<float>& out) const {
  const std::size_t old_size = out.size();
  out.resize(old_size + (end - begin));
  const float* __restrict xs = x_.data() + begin;
  const float* __restrict ys = y_.data() + begin;
  const float* __restrict zs = z_.data() + begin;
  float* __restrict squared = out.data() + old_size;
  const float px = p.x(), py = p.y(), pz = p.z();
  for (std::uint32_t i = 0; i < end - begin; ++i) {  // vectorised by the compiler
    const float dx = xs[i] - px, dy = ys[i] - py, dz = zs[i] - pz;
    squared[i] = dx * dx + dy * dy + dz * dz;
  }
}

float NeighbourGrid::inset(std::uint32_t rank) const {
  const Eigen::Array3f p(x_[rank], y_[rank], z_[rank]);
  const Eigen::Array3f cell_low = low_ + sorted_cell_[rank].cast<float>() * cell_;
  return std::min((p - cell_low).minCoeff(), (cell_low + cell_ - p).minCoeff());
}

void NeighbourGrid::nearest(std::uint32_t rank, int k, NeighbourScratch& scratch) const {
  const Point3f p(x_[rank], y_[rank], z_[rank]);
  const Eigen::Array3i centre = sorted_cell_[rank];
  const Eigen::Array3i from = (centre - 1).max(0);
  const Eigen::Array3i to = (centre + 1).min(dims_ - 1);
  std::vector<float>& candidates = scratch.distances;
  candidates.clear();
  std::size_t self = 0;
  for (int z = from.z(); z <= to.z(); ++z) {
    for (int y = from.y(); y <= to.y(); ++y) {  // cells (from.x .. to.x, y, z): one run
      const std::uint32_t begin = cell_start_[cell_of({from.x(), y, z})];
      const std::uint32_t end = cell_start_[cell_of({to.x(), y, z}) + 1];
      if (y == centre.y() && z == centre.z()) self = candidates.size() + (rank - begin);
      append_distances(p, begin, end, candidates);
    }
  }
  candidates[self] = kInfinity;
  const std::size_t wanted = static_cast<std::size_t>(k);
  if (candidates.size() <= wanted) {  // fewer than k others in the block
    nearest_by_rings(rank, k, scratch);
    return;
  }
  // Every point outside the block is at least one cell plus the inset away.
  const float reach = cell_ + inset(rank);
  const float proven = reach * reach;
  std::vector<float>& answer = scratch.nearest;
  answer.resize(candidates.size());
  float kth = kInfinity;
  std::size_t survivors = 0;
  for (const float d2 : candidates) {  // branch-free compaction below the carried bound
    answer[survivors] = d2;
    survivors += d2 < scratch.bound ? 1 : 0;
  }
  if (survivors >= wanted) {
    kth = select_smallest(answer.data(), survivors, wanted);
  } else {
    std::copy(candidates.begin(), candidates.end(), answer.begin());
    kth = select_smallest(answer.data(), answer.size(), wanted);
  }
  if (kth > proven) {
    nearest_by_rings(rank, k, scratch);
    return;
  }
  answer.resize(wanted);
  scratch.bound = kth * kBoundWidening;
}

void NeighbourGrid::nearest_by_rings(std::uint32_t rank, int k, NeighbourScratch& scratch) const {
  std::vector<float>& distances = scratch.nearest;
  distances.clear();
  const Point3f p(x_[rank], y_[rank], z_[rank]);
  const Eigen::Array3i centre = sorted_cell_[rank];
  const float from_face = inset(rank);
  const int max_ring = dims_.maxCoeff();
  const auto consider = [&](std::uint32_t other) {
    if (other == rank) return;
    const float d2 = (Point3f(x_[other], y_[other], z_[other]) - p).squaredNorm();
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
    const float reach = static_cast<float>(ring) * cell_ + from_face;
    if (static_cast<int>(distances.size()) == k && distances.back() <= reach * reach) break;
  }
  if (!distances.empty()) scratch.bound = distances.back() * kBoundWidening;
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
