#include "filters/neighbour_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "filters/distances_below.hpp"

namespace rigdesign::filters {
namespace {

// Cells beyond this count make the dense grid too large: the cell grows instead.
constexpr double kMaxGridCells = 16e6;
// The next query's pre-filter: the previous k-th squared distance times this. Wide enough that
// a neighbour in cell order almost always has k survivors, narrow enough that few survive.
constexpr float kBoundWidening = 1.6f;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// The median of three values, branch-free.
float median_of_three(float a, float b, float c) {
  return std::max(std::min(a, b), std::min(std::max(a, b), c));
}

/// The k smallest of values[0, n) moved to the front (unordered); returns the largest of them.
/// `scratch` holds n floats. Quickselect with a branch-free partition: a query keeps about 20
/// candidates for k = 10, and a partition that branches on every comparison of such a short,
/// random array (nth_element's) mispredicts half of them; here each value is written to both
/// ends of `scratch` and only the count of its side advances. Values equal to the pivot are
/// interchangeable (only their values are returned), so ties need no order.
float keep_smallest(float* values, std::size_t n, std::size_t k, float* scratch) {
  std::size_t taken = 0;  // values[0, taken) are among the k smallest
  std::size_t count = n;  // values[taken, taken + count) are undecided
  float kth = 0.0f;
  while (taken < k) {
    float* window = values + taken;
    const std::size_t need = k - taken;
    if (need == count) {
      kth = std::max(kth, *std::max_element(window, window + count));
      break;
    }
    const float pivot = median_of_three(window[0], window[count / 2], window[count - 1]);
    std::size_t less = 0, greater = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const float v = window[i];
      scratch[less] = v;
      less += v < pivot ? 1 : 0;
      scratch[count - 1 - greater] = v;
      greater += v > pivot ? 1 : 0;
    }
    std::copy(scratch, scratch + less, window);
    if (need <= less) {  // all k are below the pivot
      count = less;
      continue;
    }
    // Every value below the pivot is taken, then as many pivot copies as are needed and
    // exist; the pivot is one of the values, so at least one.
    const std::size_t equal = count - less - greater;
    const std::size_t pivots = std::min(need - less, equal);
    std::fill(window + less, window + less + pivots, pivot);
    taken += less + pivots;
    kth = pivot;
    std::copy(scratch + (count - greater), scratch + count, values + taken);
    count = greater;
  }
  return kth;
}

}  // namespace

void NeighbourGrid::build(const std::vector<model::Point3f>& points, double cell) {
  occupied_ = 0;
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
  inverse_cell_ = 1.0f / cell_;
  const std::size_t cells = static_cast<std::size_t>(dims_.x()) * dims_.y() * dims_.z();
  // Counting sort by cell: counts, then their running sums (each cell's end), then every point
  // placed counting down from its cell's end, which leaves each entry at its cell's start.
  cell_start_.assign(cells + 1, 0);
  std::vector<std::uint32_t>& point_cell_index = point_cell_index_;
  point_cell_index.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    point_cell_index[i] = static_cast<std::uint32_t>(cell_of(cell_index(points[i].array())));
    ++cell_start_[point_cell_index[i]];
  }
  for (std::size_t c = 0; c < cells; ++c) {
    occupied_ += cell_start_[c] != 0 ? 1 : 0;
    if (c > 0) cell_start_[c] += cell_start_[c - 1];
  }
  cell_start_[cells] = static_cast<std::uint32_t>(points.size());
  sorted_.resize(points.size());
  for (std::size_t i = points.size(); i-- > 0;) {
    sorted_[--cell_start_[point_cell_index[i]]] = static_cast<std::uint32_t>(i);
  }
  x_.resize(points.size());
  y_.resize(points.size());
  z_.resize(points.size());
  for (std::size_t rank = 0; rank < points.size(); ++rank) {
    const model::Point3f& p = points[sorted_[rank]];
    x_[rank] = p.x();
    y_[rank] = p.y();
    z_[rank] = p.z();
  }
}

Eigen::Array3i NeighbourGrid::cell_index(const Eigen::Array3f& position) const {
  return ((position - low_) * inverse_cell_).floor().cast<int>().max(0).min(dims_ - 1);
}

std::size_t NeighbourGrid::cell_of(const Eigen::Array3i& cell) const {
  return (static_cast<std::size_t>(cell.z()) * dims_.y() + cell.y()) * dims_.x() + cell.x();
}

double NeighbourGrid::mean_occupancy() const {
  return occupied_ == 0 ? 0.0
                        : static_cast<double>(sorted_.size()) / static_cast<double>(occupied_);
}

std::size_t NeighbourGrid::gather_below(std::uint32_t rank, float radius, float bound,
                                        std::vector<float>& out) const {
  const model::Point3f p(x_[rank], y_[rank], z_[rank]);
  const Eigen::Array3f position = p.array();
  // Truncation, not floor(): negative indices clamp to 0 either way, and the upper ends
  // are never negative (p lies in the grid); floorf is a call on CPUs without SSE 4.1.
  const Eigen::Array3i from = ((position - radius - low_) * inverse_cell_).cast<int>().max(0);
  const Eigen::Array3i to = ((position + radius - low_) * inverse_cell_).cast<int>().min(dims_ - 1);
  const auto gap = [&](int axis, int index) {  // from p to the cell's slab along one axis
    const float lower = low_[axis] + static_cast<float>(index) * cell_;
    return std::max({0.0f, lower - position[axis], position[axis] - (lower + cell_)});
  };
  // The rows' runs of the cell order go to the distance kernel in batches (one call per
  // query unless the ball spans more rows than a batch holds).
  constexpr std::size_t kBatch = 64;
  constexpr std::size_t kLanes = 8;  // the vector kernel stores whole lanes past its last value
  IndexRun runs[kBatch];
  std::size_t batched = 0;
  std::size_t batched_points = 0;
  std::size_t kept = 0;
  const auto flush = [&] {
    if (out.size() < kept + batched_points + kLanes) {
      out.resize(2 * (kept + batched_points + kLanes));
    }
    kept += append_distances_below(x_.data(), y_.data(), z_.data(), runs, batched, p.x(), p.y(),
                                   p.z(), bound, out.data() + kept);
    batched = 0;
    batched_points = 0;
  };
  const auto append = [&](std::uint32_t begin, std::uint32_t end) {
    if (begin == end) return;
    if (batched == kBatch) flush();
    runs[batched++] = {begin, end};
    batched_points += end - begin;
  };
  for (int z = from.z(); z <= to.z(); ++z) {
    const float z_gap = gap(2, z);
    const float z_room = radius * radius - z_gap * z_gap;
    if (z_room < 0) continue;
    for (int y = from.y(); y <= to.y(); ++y) {
      const float y_gap = gap(1, y);
      const float room = z_room - y_gap * y_gap;
      if (room < 0) continue;
      const float chord = std::sqrt(room);
      const int x0 =
          std::max(from.x(), static_cast<int>((p.x() - chord - low_.x()) * inverse_cell_));
      const int x1 = std::min(to.x(), static_cast<int>((p.x() + chord - low_.x()) * inverse_cell_));
      if (x0 > x1) continue;
      const std::uint32_t begin = cell_start_[cell_of({x0, y, z})];
      const std::uint32_t end = cell_start_[cell_of({x1, y, z}) + 1];
      if (rank >= begin && rank < end) {  // the query point itself is no neighbour
        append(begin, rank);
        append(rank + 1, end);
      } else {
        append(begin, end);
      }
    }
  }
  flush();
  return kept;
}

void NeighbourGrid::nearest(std::uint32_t rank, int k, NeighbourScratch& scratch) const {
  const Eigen::Array3f position(x_[rank], y_[rank], z_[rank]);
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
    std::size_t survivors = gather_below(rank, radius, bound, answer);
    // Index ranges spanning the grid do not mean the ball holds it: rows are trimmed.
    const Eigen::Array3f high = low_ + dims_.cast<float>() * cell_;
    const bool whole_grid =
        radius * radius >= (position - low_).max(high - position).square().sum();
    if (survivors >= wanted || whole_grid) {
      if (survivors < wanted) {  // the ball holds the whole grid: every other point counts
        survivors = gather_below(rank, radius, kInfinity, answer);
      }
      if (scratch.distances.size() < survivors) scratch.distances.resize(survivors);
      const float kth = keep_smallest(answer.data(), survivors, wanted, scratch.distances.data());
      answer.resize(wanted);
      scratch.bound = kth * kBoundWidening;
      return;
    }
    bound *= 4.0f;  // too few inside: twice the radius
  }
}

bool NeighbourGrid::has_neighbours(std::uint32_t rank, float squared_radius,
                                   std::size_t enough) const {
  if (enough == 0) return true;
  const float px = x_[rank], py = y_[rank], pz = z_[rank];
  const Eigen::Array3f position(px, py, pz);
  // The cells are taken for a ball a hair larger than the radius, so float rounding in the
  // cell test cannot drop a point the distance test keeps (as in `nearest`).
  const float radius = std::sqrt(squared_radius) * (1.0f + 1e-5f) + 1e-7f;
  const Eigen::Array3i from = ((position - radius - low_) * inverse_cell_).cast<int>().max(0);
  const Eigen::Array3i to = ((position + radius - low_) * inverse_cell_).cast<int>().min(dims_ - 1);
  const Eigen::Array3i own = cell_index(position);
  const auto gap = [&](int axis, int index) {  // from the point to the cell's slab on one axis
    const float lower = low_[axis] + static_cast<float>(index) * cell_;
    return std::max({0.0f, lower - position[axis], position[axis] - (lower + cell_)});
  };
  // Counted in blocks the compiler vectorises, checked after each: a dense row stops early.
  constexpr std::uint32_t kBlock = 32;
  std::size_t found = 0;
  const auto enough_in_row = [&](int y, int z) {
    const float y_gap = gap(1, y);
    const float z_gap = gap(2, z);
    const float room = radius * radius - z_gap * z_gap - y_gap * y_gap;
    if (room < 0) return false;
    const float chord = std::sqrt(room);
    const int x0 = std::max(from.x(), static_cast<int>((px - chord - low_.x()) * inverse_cell_));
    const int x1 = std::min(to.x(), static_cast<int>((px + chord - low_.x()) * inverse_cell_));
    if (x0 > x1) return false;
    const std::uint32_t begin = cell_start_[cell_of({x0, y, z})];
    const std::uint32_t end = cell_start_[cell_of({x1, y, z}) + 1];
    // The query counts itself (distance 0) when its row holds it: one more is needed there.
    const std::size_t needed = enough + (rank >= begin && rank < end ? 1 : 0);
    for (std::uint32_t block = begin; block < end; block += kBlock) {
      const std::uint32_t block_end = std::min(end, block + kBlock);
      std::size_t inside = 0;
      for (std::uint32_t i = block; i < block_end; ++i) {
        const float dx = x_[i] - px;
        const float dy = y_[i] - py;
        const float dz = z_[i] - pz;
        inside += dx * dx + dy * dy + dz * dz <= squared_radius ? 1 : 0;
      }
      found += inside;
      if (found >= needed) return true;
    }
    if (needed > enough) --found;  // the query itself, counted above
    return false;
  };
  if (enough_in_row(own.y(), own.z())) return true;
  for (int z = from.z(); z <= to.z(); ++z) {
    for (int y = from.y(); y <= to.y(); ++y) {
      if (y == own.y() && z == own.z()) continue;
      if (enough_in_row(y, z)) return true;
    }
  }
  return false;
}

void build_grid_for(const std::vector<model::Point3f>& points, int per_cell, NeighbourGrid& grid) {
  if (points.size() < 2) {
    grid.build(points, 1.0);
    return;
  }
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
  grid.build(points, guess);
  const double occupancy = grid.mean_occupancy();
  if (occupancy >= 0.5 * per_cell && occupancy <= 2.0 * per_cell) return;
  const double refined = occupancy > 0 ? guess * std::sqrt(per_cell / occupancy) : guess;
  grid.build(points, std::max(refined, diagonal * 1e-6));
}

}  // namespace rigdesign::filters
