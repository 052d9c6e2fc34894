#pragma once
/// The cells a straight segment crosses, by Amanatides and Woo's "A Fast Voxel Traversal
/// Algorithm for Ray Tracing" (1987), on a flat array. Coordinates are in cell units (world
/// position minus the grid's corner, divided by the cell size), so one routine serves the 2D
/// obstacle layer, the 3D voxel layer and the occupancy comparison's TSDF.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rigdesign::costmap::detail {

template <int Dim>
using GridPoint = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using GridSize = Eigen::Matrix<int, Dim, 1>;
template <int Dim>
using GridStride = Eigen::Matrix<std::ptrdiff_t, Dim, 1>;

/// Clips the segment a -> b to the box [0, size] (Liang-Barsky). False when it misses the box;
/// `end_clipped` tells whether b was moved onto the box's boundary.
template <int Dim>
bool clip_to_grid(GridPoint<Dim>& a, GridPoint<Dim>& b, const GridSize<Dim>& size,
                  bool& end_clipped) {
  double t0 = 0.0;
  double t1 = 1.0;
  const GridPoint<Dim> d = b - a;
  for (int k = 0; k < Dim; ++k) {
    const double high = static_cast<double>(size[k]);
    if (d[k] == 0.0) {
      if (a[k] < 0.0 || a[k] > high) return false;
      continue;
    }
    double enter = -a[k] / d[k];
    double leave = (high - a[k]) / d[k];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  end_clipped = t1 < 1.0;
  const GridPoint<Dim> start = a;
  if (t0 > 0.0) a = start + t0 * d;
  if (end_clipped) b = start + t1 * d;
  return true;
}

/// The cell holding p, clamped into the grid (p is inside or on the box after clipping).
template <int Dim>
Eigen::Matrix<int, Dim, 1> clamped_cell(const GridPoint<Dim>& p, const GridSize<Dim>& size) {
  Eigen::Matrix<int, Dim, 1> cell;
  for (int k = 0; k < Dim; ++k) {
    cell[k] = std::clamp(static_cast<int>(std::floor(p[k])), 0, size[k] - 1);
  }
  return cell;
}

/// True when p lies in a cell of the grid (the half-open box [0, size)).
template <int Dim>
bool inside_grid(const GridPoint<Dim>& p, const GridSize<Dim>& size) {
  for (int k = 0; k < Dim; ++k) {
    if (!(p[k] >= 0.0 && p[k] < static_cast<double>(size[k]))) return false;
  }
  return true;
}

/// Calls visit(flat index) for every cell the segment a -> b crosses, from a's cell to b's,
/// b's cell only when `include_end`. Both points must be inside the box (clip first). The
/// walk takes exactly as many steps per axis as the end cells differ, so rounding can never
/// step past the end cell or out of the grid.
template <int Dim, class Visit>
inline void walk_cells(const GridPoint<Dim>& a, const GridPoint<Dim>& b, const GridSize<Dim>& size,
                       const GridStride<Dim>& stride, bool include_end, Visit&& visit) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  const auto first = clamped_cell<Dim>(a, size);
  const auto last = clamped_cell<Dim>(b, size);
  std::ptrdiff_t index = 0;
  double t_max[Dim];
  double t_delta[Dim];
  std::ptrdiff_t step[Dim];
  int remaining[Dim];
  int total = 0;
  for (int k = 0; k < Dim; ++k) {
    index += static_cast<std::ptrdiff_t>(first[k]) * stride[k];
    remaining[k] = std::abs(last[k] - first[k]);
    total += remaining[k];
    if (remaining[k] == 0) {
      t_max[k] = kNever;
      t_delta[k] = kNever;
      step[k] = 0;
      continue;
    }
    const bool up = last[k] > first[k];  // then b[k] > a[k]: floor is monotonic
    step[k] = up ? stride[k] : -stride[k];
    t_delta[k] = 1.0 / std::abs(b[k] - a[k]);
    t_max[k] = (up ? (first[k] + 1 - a[k]) : (a[k] - first[k])) * t_delta[k];
  }
  if constexpr (Dim == 3) {
    // The same walk with every quantity in a named scalar, so they stay in registers; an
    // array indexed by the axis goes through memory at every step (twice as slow, measured).
    double tx = t_max[0], ty = t_max[1], tz = t_max[2];
    int rx = remaining[0], ry = remaining[1], rz = remaining[2];
    for (int n = 0; n < total; ++n) {
      visit(index);
      if (tx < ty && tx < tz) {
        index += step[0];
        tx = --rx == 0 ? kNever : tx + t_delta[0];
      } else if (ty < tz) {
        index += step[1];
        ty = --ry == 0 ? kNever : ty + t_delta[1];
      } else {
        index += step[2];
        tz = --rz == 0 ? kNever : tz + t_delta[2];
      }
    }
  } else {
    for (int n = 0; n < total; ++n) {
      visit(index);
      int axis = 0;
      for (int k = 1; k < Dim; ++k) {
        if (t_max[k] < t_max[axis]) axis = k;
      }
      index += step[axis];
      if (--remaining[axis] == 0) {
        t_max[axis] = kNever;
      } else {
        t_max[axis] += t_delta[axis];
      }
    }
  }
  if (include_end) visit(index);
}

}  // namespace rigdesign::costmap::detail
