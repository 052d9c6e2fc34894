#pragma once
// A sector threshold at one angle restated as the covered cells (floor columns) it takes:
// what the branch and bound and its robustness bound compare the classes' counts with.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "rigdesign/select/class_coverage.hpp"
#include "rigdesign/select/search.hpp"

namespace rigdesign::select {

// Covered cells (floor columns) needed at one angle of a sector: the smallest count whose
// share meets the threshold exactly as meets() decides it on a share (total + 1: none does).
struct Need {
  std::size_t sector = 0;
  std::size_t angle = 0;
  std::int64_t cells = 0;
  std::int64_t floor = 0;
  double min_complete = 0.0;
  double min_floor = 0.0;
};

std::vector<Need> needs_of(const std::vector<SearchSector>& sectors, const ClassCoverage& classes);

inline bool met(const CellCounts& counts, const Need& need) {
  return counts.cells >= need.cells && counts.floor >= need.floor;
}

// What buying some option adds at least, each part minimised on its own: a lower bound on
// whichever option a completion buys (its CPU load and bandwidth can raise the CPU and
// transfer prices as much as its own price). Infinite: no option does what is asked.
struct LeastAddition {
  double price = 0.0;
  double bandwidth = 0.0;
  double cpu = 0.0;

  static LeastAddition none() {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    return {kNone, kNone, kNone};
  }
  // The option's own transfer components count with its price: both come with it alone.
  static LeastAddition of(const SearchOption& option) {
    return {option.price + option.transfer_price, option.bandwidth, option.cpu};
  }
  bool possible() const { return std::isfinite(price); }
  // Part by part: the smaller (either option may be the one bought).
  LeastAddition least(const LeastAddition& other) const {
    return {std::min(price, other.price), std::min(bandwidth, other.bandwidth),
            std::min(cpu, other.cpu)};
  }
  // Part by part: the larger (both needs must be met, by one option or more).
  LeastAddition most(const LeastAddition& other) const {
    return {std::max(price, other.price), std::max(bandwidth, other.bandwidth),
            std::max(cpu, other.cpu)};
  }
  LeastAddition plus(const LeastAddition& other) const {
    return {price + other.price, bandwidth + other.bandwidth, cpu + other.cpu};
  }
};

// A need not yet met at a search node, and the least a completion still adds for it: a child
// that adds an option covering nothing at `angle` still adds at least `addition`.
struct UnmetNeed {
  std::size_t angle = 0;
  LeastAddition addition;
};

}  // namespace rigdesign::select
