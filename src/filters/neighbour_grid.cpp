#include "filters/neighbour_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rigdesign::filters {
namespace {

// Cells beyond this count make the dense grid too large: the cell grows instead.
constexpr double kMaxGridCells = 16e6;
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

NeighbourGrid::NeighbourGrid(const std::vector<model::Point3f>& points, double cell) {
  low_ = Eigen::Array3f::Constant(kInfinity);
  Eigen::Array3f high = -low_;
  for (const model::Point3f& p : points) {
    low_ = low_.min(p.array());
    high = high.max(p.array());
  }
  if (points.empty()) low_ = high = Eigen::Array3f::Zero();
  // A cell wider than the cloud is the cloud; one too small to be a float is the smallest
  // float (then grown below). Cell counts are taken in double so no extent overflows an int.
  const double widest = std::max(1e-3, static_cast<double>((high - low_).maxCoeff()));
  cell_ = static_cast<float>(std::clamp(cell, double{std::numeric_limits<float>::min()}, widest));
  const Eigen::Array3d span = (high - low_).cast<double>();
  auto cells_per_axis = [&] { return (span / static_cast<double>(cell_)).floor() + 1.0; };
  while (cells_per_axis().prod() > kMaxGridCells) cell_ *= 1.5f;
  dims_ = cells_per_axis().cast<int>();
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
    const model::Point3f& p = points[sorted_[rank]];
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
  return occupied_ == 0 ? 0.0
                        : static_cast<double>(sorted_.size()) / static_cast<double>(occupied_);
}

std::size_t NeighbourGrid::append_distances(const model::Point3f& p, std::uint32_t begin,
                                            std::uint32_t end, std::vector<float>& out,
                                            std::size_t size) const {
  if (out.size() < size + (end - begin)) out.resize(2 * (size + (end - begin)));
  const float* __restrict xs = x_.data() + begin;
  const float* __restrict ys = y_.data() + begin;
  const float* __restrict zs = z_.data() + begin;
  float* __restrict squared = out.data() + size;
  const float px = p.x(), py = p.y(), pz = p.z();
  for (std::uint32_t i = 0; i < end - begin; ++i) {  // vectorised by the compiler
    const float dx = xs[i] - px, dy = ys[i] - py, dz = zs[i] - pz;
    squared[i] = dx * dx + dy * dy + dz * dz;
  }
  return size + (end - begin);
}

void NeighbourGrid::nearest(std::uint32_t rank, int k, NeighbourScratch& scratch) const {
  const model::Point3f p(x_[rank], y_[rank], z_[rank]);
  const Eigen::Array3f position = p.array();
  std::vector<float>& candidates = scratch.distances;
  std::vector<float>& answer = scratch.nearest;
  const std::size_t others_in_cloud = sorted_.size() - 1;
  const std::size_t wanted = std::min(static_cast<std::size_t>(k), others_in_cloud);
  answer.clear();
  if (wanted == 0) return;
  float bound = scratch.bound > 0 ? scratch.bound : cell_ * cell_;
  for (;;) {
    // Every point nearer than sqrt(bound) lies in a cell the ball touches: visit those, row by
    // row, each row trimmed to the ball's chord. The ball is taken a hair larger than the
    // bound so float rounding in the cell test cannot drop a point the distance test keeps.
    const float radius = std::sqrt(bound) * (1.0f + 1e-5f) + 1e-7f;
    // Truncation, not floor(): negative indices clamp to 0 either way, and the upper ends
    // are never negative (p lies in the grid); floorf is a call on CPUs without SSE 4.1.
    const Eigen::Array3i from = ((position - radius - low_) / cell_).cast<int>().max(0);
    const Eigen::Array3i to = ((position + radius - low_) / cell_).cast<int>().min(dims_ - 1);
    const auto gap = [&](int axis, int index) {  // from p to the cell's slab along one axis
      const float lower = low_[axis] + static_cast<float>(index) * cell_;
      return std::max({0.0f, lower - position[axis], position[axis] - (lower + cell_)});
    };
    std::size_t size = 0;
    std::size_t self = std::numeric_limits<std::size_t>::max();
    for (int z = from.z(); z <= to.z(); ++z) {
      const float z_gap = gap(2, z);
      const float z_room = radius * radius - z_gap * z_gap;
      if (z_room < 0) continue;
      for (int y = from.y(); y <= to.y(); ++y) {
        const float y_gap = gap(1, y);
        const float room = z_room - y_gap * y_gap;
        if (room < 0) continue;
        const float chord = std::sqrt(room);
        const int x0 = std::max(from.x(), static_cast<int>((p.x() - chord - low_.x()) / cell_));
        const int x1 = std::min(to.x(), static_cast<int>((p.x() + chord - low_.x()) / cell_));
        if (x0 > x1) continue;
        const std::uint32_t begin = cell_start_[cell_of({x0, y, z})];
        const std::uint32_t end = cell_start_[cell_of({x1, y, z}) + 1];
        if (rank >= begin && rank < end) self = size + (rank - begin);
        size = append_distances(p, begin, end, candidates, size);
      }
    }
    if (self < size) candidates[self] = kInfinity;
    if (answer.size() < size) answer.resize(size);
    std::size_t survivors = 0;
    for (std::size_t i = 0; i < size; ++i) {  // branch-free compaction below the bound
      answer[survivors] = candidates[i];
      survivors += candidates[i] < bound ? 1 : 0;
    }
    // Index ranges spanning the grid do not mean the ball holds it: rows are trimmed.
    const Eigen::Array3f high = low_ + dims_.cast<float>() * cell_;
    const bool whole_grid =
        radius * radius >= (position - low_).max(high - position).square().sum();
    if (survivors >= wanted || whole_grid) {
      if (survivors < wanted) {  // the ball holds the whole grid: every other point counts
        std::copy(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(size),
                  answer.begin());
        survivors = size;
      }
      const float kth = select_smallest(answer.data(), survivors, wanted);
      answer.resize(wanted);
      scratch.bound = kth * kBoundWidening;
      return;
    }
    bound *= 4.0f;  // too few inside: twice the radius
  }
}

NeighbourGrid grid_for(const std::vector<model::Point3f>& points, int per_cell) {
  if (points.size() < 2) return NeighbourGrid(points, 1.0);
  Eigen::Array3f low = points.front().array();
  Eigen::Array3f high = low;
  for (const model::Point3f& p : points) {
    low = low.min(p.array());
    high = high.max(p.array());
  }
  const double diagonal = std::max(1e-6, static_cast<double>((high - low).matrix().norm()));
  // Points on surfaces: spacing ~ diagonal / sqrt(n). The grid built on that guess is kept
  // when its occupancy is within a factor 2 of the aim, else rebuilt once from it.
  const double guess = 2.0 * diagonal / std::sqrt(static_cast<double>(points.size()));
  NeighbourGrid grid(points, guess);
  const double occupancy = grid.mean_occupancy();
  if (occupancy >= 0.5 * per_cell && occupancy <= 2.0 * per_cell) return grid;
  const double refined = occupancy > 0 ? guess * std::sqrt(per_cell / occupancy) : guess;
  return NeighbourGrid(points, std::max(refined, diagonal * 1e-6));
}

}  // namespace rigdesign::filters
