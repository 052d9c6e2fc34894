#pragma once
/// A 2D window of square cells on a world-fixed lattice that rolls with the robot (DESIGN.md
/// section 7). The window's origin is an integer lattice index, so recentring moves whole
/// cells: the overlap is copied unchanged and only cells entering the window are reset.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::costmap {

/// A cell of a window: 0 <= x < width, 0 <= y < height.
struct CellIndex {
  int x = 0;
  int y = 0;
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

/// Where a window lies. Lattice cell (i, j) covers [i r, (i + 1) r) x [j r, (j + 1) r) in the
/// world frame (r the resolution); the window's cell (x, y) is lattice cell origin_cell + (x, y).
struct GridWindow {
  int width = 0;                                          ///< cells along world x
  int height = 0;                                         ///< cells along world y
  double resolution = 0.05;                               ///< cell side [m]
  Eigen::Vector2i origin_cell = Eigen::Vector2i::Zero();  ///< lattice index of cell (0, 0)

  /// World position of the lower-left corner of cell (0, 0) [m] (map_server's `origin`).
  model::Vec2 origin() const { return origin_cell.cast<double>() * resolution; }
  std::size_t size() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
  }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  /// Lattice index of the cell holding a world point: floor(p / r).
  Eigen::Vector2i lattice_of(const model::Vec2& p_world) const {
    return {static_cast<int>(std::floor(p_world.x() / resolution)),
            static_cast<int>(std::floor(p_world.y() / resolution))};
  }
  /// The window cell holding a world point, if inside the window.
  std::optional<CellIndex> cell_of(const model::Vec2& p_world) const {
    const Eigen::Vector2i local = lattice_of(p_world) - origin_cell;
    if (!contains(local.x(), local.y())) return std::nullopt;
    return CellIndex{local.x(), local.y()};
  }
  /// World position of a cell's centre [m].
  model::Vec2 centre_of(int x, int y) const {
    return origin() + resolution * model::Vec2(x + 0.5, y + 0.5);
  }
  /// The origin that puts the lattice cell holding `centre_world` at cell (width/2, height/2).
  Eigen::Vector2i origin_centred_on(const model::Vec2& centre_world) const {
    return lattice_of(centre_world) - Eigen::Vector2i(width / 2, height / 2);
  }
};

namespace detail {

/// Moves a window's blocks (`block` values per cell, row-major cells) so that the cell at
/// lattice index L keeps its values when the origin moves by `shift`; cells that enter the
/// window get `fill`. `scratch` is reused between calls to avoid allocating.
template <class T>
void shift_blocks(std::vector<T>& values, std::vector<T>& scratch, int width, int height,
                  std::size_t block, const Eigen::Vector2i& shift, T fill) {
  if (shift.isZero()) return;
  scratch.assign(values.size(), fill);
  // New cell (x, y) is old cell (x + shift.x, y + shift.y).
  const int x_begin = std::max(0, -shift.x());
  const int x_end = std::min(width, width - shift.x());
  const int y_begin = std::max(0, -shift.y());
  const int y_end = std::min(height, height - shift.y());
  if (x_begin < x_end) {
    const std::size_t run = static_cast<std::size_t>(x_end - x_begin) * block;
    for (int y = y_begin; y < y_end; ++y) {
      const std::size_t to = (static_cast<std::size_t>(y) * width + x_begin) * block;
      const std::size_t from =
          (static_cast<std::size_t>(y + shift.y()) * width + (x_begin + shift.x())) * block;
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(from), run,
                  scratch.begin() + static_cast<std::ptrdiff_t>(to));
    }
  }
  values.swap(scratch);
}

}  // namespace detail

/// Values of type T on a rolling window. Deterministic; not thread-safe.
template <class T>
class RollingGrid {
 public:
  RollingGrid() = default;
  /// Every cell starts at `fill`, which is also what cells entering the window get.
  RollingGrid(const GridWindow& window, T fill)
      : window_(window), fill_(fill), cells_(window.size(), fill) {}

  const GridWindow& window() const { return window_; }
  int width() const { return window_.width; }
  int height() const { return window_.height; }
  T fill_value() const { return fill_; }

  T& at(int x, int y) { return cells_[window_.index(x, y)]; }
  const T& at(int x, int y) const { return cells_[window_.index(x, y)]; }
  std::vector<T>& cells() { return cells_; }
  const std::vector<T>& cells() const { return cells_; }
  void reset() { std::fill(cells_.begin(), cells_.end(), fill_); }
  /// Takes `window` as it is (size, resolution, origin), every cell at the fill value.
  void reshape(const GridWindow& window) {
    window_ = window;
    cells_.assign(window.size(), fill_);
  }

  /// Moves the window so its origin is lattice cell `origin_cell`: the overlap keeps its
  /// values, cells entering the window get the fill value.
  void move_origin(const Eigen::Vector2i& origin_cell) {
    detail::shift_blocks(cells_, scratch_, window_.width, window_.height, 1,
                         Eigen::Vector2i(origin_cell - window_.origin_cell), fill_);
    window_.origin_cell = origin_cell;
  }
  /// Centres the window on a world point [m] (see GridWindow::origin_centred_on).
  void recentre(const model::Vec2& centre_world) {
    move_origin(window_.origin_centred_on(centre_world));
  }

 private:
  GridWindow window_;
  T fill_{};
  std::vector<T> cells_;
  std::vector<T> scratch_;
};

/// A costmap layer's grid (values from cost_values.hpp).
using CostGrid = RollingGrid<std::uint8_t>;

}  // namespace rigdesign::costmap
