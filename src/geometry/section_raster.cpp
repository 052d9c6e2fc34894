#include "rigdesign/geometry/section_raster.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace rigdesign::geometry {
namespace {

constexpr int kWordBits = 64;

std::size_t words_for(std::size_t bits) {
  return (bits + kWordBits - 1) / kWordBits;
}

void set_bits(std::vector<std::uint64_t>& words, std::size_t first, std::size_t end) {
  while (first < end) {
    const std::size_t word = first / kWordBits;
    const std::size_t offset = first % kWordBits;
    const std::size_t count = std::min<std::size_t>(kWordBits - offset, end - first);
    const std::uint64_t mask =
        count == kWordBits ? ~std::uint64_t{0} : ((std::uint64_t{1} << count) - 1) << offset;
    words[word] |= mask;
    first += count;
  }
}

// Generic x86-64 has no POPCNT instruction, so std::popcount becomes a libgcc call per word;
// a second copy compiled for POPCNT is chosen at load time where the CPU has it (one binary
// for every x86-64 machine).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RIGDESIGN_POPCNT_CLONES __attribute__((target_clones("popcnt", "default")))
#else
#define RIGDESIGN_POPCNT_CLONES
#endif

RIGDESIGN_POPCNT_CLONES std::size_t popcount(const std::vector<std::uint64_t>& words) {
  std::size_t total = 0;
  for (const std::uint64_t word : words) total += static_cast<std::size_t>(std::popcount(word));
  return total;
}

// First cell index whose centre (index + 0.5) * size is >= value.
int first_centre_at_or_after(double value, double size) {
  return static_cast<int>(std::ceil(value / size - 0.5));
}

}  // namespace

SectionRaster::SectionRaster(const RasterGrid& grid)
    : grid_(grid),
      cells_(words_for(static_cast<std::size_t>(grid.columns) * grid.rows)),
      floor_(words_for(static_cast<std::size_t>(grid.columns))) {}

void SectionRaster::set_column_run(int column, int first_row, int end_row) {
  first_row = std::max(first_row, 0);
  end_row = std::min(end_row, grid_.rows);
  if (first_row >= end_row) return;
  const std::size_t base = static_cast<std::size_t>(column) * grid_.rows;
  set_bits(cells_, base + first_row, base + end_row);
}

void SectionRaster::set_floor(int column) {
  set_bits(floor_, static_cast<std::size_t>(column), static_cast<std::size_t>(column) + 1);
}

SectionRaster& SectionRaster::operator|=(const SectionRaster& other) {
  for (std::size_t i = 0; i < cells_.size(); ++i) cells_[i] |= other.cells_[i];
  for (std::size_t i = 0; i < floor_.size(); ++i) floor_[i] |= other.floor_[i];
  return *this;
}

SectionRaster& SectionRaster::operator&=(const SectionRaster& other) {
  for (std::size_t i = 0; i < cells_.size(); ++i) cells_[i] &= other.cells_[i];
  for (std::size_t i = 0; i < floor_.size(); ++i) floor_[i] &= other.floor_[i];
  return *this;
}

double SectionRaster::complete_share() const {
  return static_cast<double>(popcount(cells_)) / (static_cast<double>(grid_.columns) * grid_.rows);
}

double SectionRaster::floor_share() const {
  return static_cast<double>(popcount(floor_)) / grid_.columns;
}

namespace {

RIGDESIGN_POPCNT_CLONES std::size_t union_popcount(const std::vector<std::uint64_t>& a,
                                                   const std::vector<std::uint64_t>& b) {
  std::size_t total = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    total += static_cast<std::size_t>(std::popcount(a[i] | b[i]));
  return total;
}

}  // namespace

double SectionRaster::complete_share_with(const SectionRaster& other) const {
  return static_cast<double>(union_popcount(cells_, other.cells_)) /
         (static_cast<double>(grid_.columns) * grid_.rows);
}

double SectionRaster::floor_share_with(const SectionRaster& other) const {
  return static_cast<double>(union_popcount(floor_, other.floor_)) / grid_.columns;
}

bool SectionRaster::any() const {
  return std::any_of(cells_.begin(), cells_.end(), [](std::uint64_t w) { return w != 0; });
}

bool SectionRaster::test(int column, int row) const {
  const std::size_t bit = static_cast<std::size_t>(column) * grid_.rows + row;
  return (cells_[bit / kWordBits] >> (bit % kWordBits)) & 1U;
}

SectionRaster rasterize(const MountedFov& fov, const SectionFrame& frame, const RasterGrid& grid) {
  SectionRaster raster(grid);
  if (!fov.may_reach_azimuth(frame.theta)) return raster;
  const double column_width = frame.width() / grid.columns;
  const double row_height = frame.h / grid.rows;
  // Columns whose horizontal distance from the sensor exceeds its max range see nothing:
  // |rho * e_theta - o|^2 <= max^2 bounds rho to [rho_near, rho_far].
  const model::Vec2 outward(std::cos(frame.theta), std::sin(frame.theta));
  const model::Vec2 o = fov.origin().head<2>();
  const double along = o.dot(outward);
  const double reach2 =
      fov.mode().max_range * fov.mode().max_range - (o.squaredNorm() - along * along);
  if (reach2 < 0) return raster;
  const double rho_near = along - std::sqrt(reach2);
  const double rho_far = along + std::sqrt(reach2);
  const int first_column =
      std::max(0, static_cast<int>(std::floor((rho_near - frame.r) / column_width)));
  const int end_column =
      std::min(grid.columns, static_cast<int>(std::ceil((rho_far - frame.r) / column_width)) + 1);
  for (int column = first_column; column < end_column; ++column) {
    const double rho = frame.r + (column + 0.5) * column_width;
    const IntervalSet covered = column_coverage(fov, frame, rho);
    for (const auto& [low, high] : covered.intervals()) {
      raster.set_column_run(column, first_centre_at_or_after(low, row_height),
                            first_centre_at_or_after(high, row_height));
    }
  }
  const IntervalSet floor = floor_coverage(fov, frame);
  for (const auto& [low, high] : floor.intervals()) {
    const int first = std::max(0, first_centre_at_or_after(low - frame.r, column_width));
    const int end = std::min(grid.columns, first_centre_at_or_after(high - frame.r, column_width));
    for (int column = first; column < end; ++column) raster.set_floor(column);
  }
  return raster;
}

}  // namespace rigdesign::geometry
