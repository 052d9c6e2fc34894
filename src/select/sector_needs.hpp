#pragma once
// A sector threshold at one angle restated as the covered cells (floor columns) it takes:
// what the branch and bound and its robustness bound compare the classes' counts with.
#include <cstdint>
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

}  // namespace rigdesign::select
