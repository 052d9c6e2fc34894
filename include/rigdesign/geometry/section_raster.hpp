#pragma once
/// The fast path: a cross-section rasterised into a bitset of cells (union = OR,
/// area = popcount), for the selection search that evaluates thousands of rigs.
/// A cell counts as covered when its centre is; each column is filled from the exact
/// column_coverage intervals, so the only error is the cell size.
#include <cstdint>
#include <vector>

#include "rigdesign/geometry/cross_section.hpp"

namespace rigdesign::geometry {

struct RasterGrid {
  int columns = 300;  ///< cells along rho
  int rows = 100;     ///< cells along z
};

class SectionRaster {
 public:
  SectionRaster() = default;
  explicit SectionRaster(const RasterGrid& grid);

  void set_column_run(int column, int first_row, int end_row);
  void set_floor(int column);
  SectionRaster& operator|=(const SectionRaster& other);
  SectionRaster& operator&=(const SectionRaster& other);

  /// Covered cells / all cells.
  double complete_share() const;
  /// Covered floor columns / all columns.
  double floor_share() const;
  bool any() const;
  bool test(int column, int row) const;

  const RasterGrid& grid() const { return grid_; }

  /// Shares of the union with `other` (same grid), without building it.
  double complete_share_with(const SectionRaster& other) const;
  double floor_share_with(const SectionRaster& other) const;

  /// The bits themselves, for the search's compressed classes: cell bit column * rows + row,
  /// floor bit column.
  const std::vector<std::uint64_t>& cell_words() const { return cells_; }
  const std::vector<std::uint64_t>& floor_words() const { return floor_; }

 private:
  RasterGrid grid_;
  std::vector<std::uint64_t> cells_;  // column-major: bit column * rows + row
  std::vector<std::uint64_t> floor_;  // bit per column
};

/// Rasterises what `fov` sees in `frame` (cells and the floor).
SectionRaster rasterize(const MountedFov& fov, const SectionFrame& frame, const RasterGrid& grid);

}  // namespace rigdesign::geometry
