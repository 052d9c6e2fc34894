#include "select/sector_needs.hpp"

#include <algorithm>
#include <cmath>

#include "select/search_rules.hpp"

namespace rigdesign::select {
namespace {

std::int64_t smallest_count_meeting(double threshold, std::int64_t total) {
  // share = count / total is monotone in count: start near the answer, then settle it with
  // the same floating-point comparison meets() makes.
  std::int64_t count =
      std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((threshold - kThresholdSlack) *
                                                                    static_cast<double>(total))) -
                                   1,
                               0, total);
  while (count <= total &&
         !meets(static_cast<double>(count) / static_cast<double>(total), threshold))
    ++count;
  while (count > 0 && meets(static_cast<double>(count - 1) / static_cast<double>(total), threshold))
    --count;
  return count;
}

}  // namespace

std::vector<Need> needs_of(const std::vector<SearchSector>& sectors, const ClassCoverage& classes) {
  std::vector<Need> needs;
  for (std::size_t s = 0; s < sectors.size(); ++s) {
    const SearchSector& sector = sectors[s];
    for (const int a : sector.angles) {
      const CellCounts total = classes.total(static_cast<std::size_t>(a));
      needs.push_back({s, static_cast<std::size_t>(a),
                       smallest_count_meeting(sector.min_complete, total.cells),
                       smallest_count_meeting(sector.min_floor, total.floor), sector.min_complete,
                       sector.min_floor});
    }
  }
  return needs;
}

}  // namespace rigdesign::select
