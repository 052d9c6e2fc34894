// The brute force: every assignment on the raw rasters, the reference the branch and bound
// (on compressed classes) is tested against.
#include "rigdesign/select/search.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "rigdesign/geometry/housing_clearance.hpp"
#include "select/search_rules.hpp"

namespace rigdesign::select {
namespace {

// Each sector's smallest margin over its angles, smallest first.
std::vector<double> sector_margins(const SearchProblem& problem,
                                   const std::vector<geometry::SectionRaster>& sections) {
  std::vector<double> margins;
  for (const SearchSector& sector : problem.sectors) {
    double margin = std::numeric_limits<double>::infinity();
    for (const int a : sector.angles) {
      margin = std::min({margin, sections[a].complete_share() - sector.min_complete,
                         sections[a].floor_share() - sector.min_floor});
    }
    margins.push_back(margin);
  }
  std::sort(margins.begin(), margins.end());
  return margins;
}

bool meets_sectors(const std::vector<SearchSector>& sectors,
                   const std::vector<geometry::SectionRaster>& sections) {
  for (const SearchSector& sector : sectors) {
    for (const int a : sector.angles) {
      if (!meets(sections[a].complete_share(), sector.min_complete) ||
          !meets(sections[a].floor_share(), sector.min_floor)) {
        return false;
      }
    }
  }
  return true;
}

// Whether the rig `choice` still meets the robustness sectors after every failure the
// problem asks it to survive: each chosen sensor alone, and every sensor that does not
// survive the condition at once.
bool survives(const SearchProblem& problem, const std::vector<int>& choice) {
  const Robustness& robust = problem.robustness;
  if (!robust.any()) return true;
  const auto union_without = [&](const auto& dropped) {
    std::vector<geometry::SectionRaster> sections;
    for (const geometry::RasterGrid& grid : problem.grids) sections.emplace_back(grid);
    for (std::size_t k = 0; k < choice.size(); ++k) {
      if (choice[k] < 0 || dropped(k)) continue;
      const SearchOption& option = problem.slots[k][choice[k]];
      for (const SearchSector& sector : robust.sectors) {
        for (const int a : sector.angles) sections[a] |= option.section(a);
      }
    }
    return sections;
  };
  if (robust.single_failure) {
    for (std::size_t j = 0; j < choice.size(); ++j) {
      if (choice[j] < 0) continue;
      if (!meets_sectors(robust.sectors, union_without([&](std::size_t k) { return k == j; })))
        return false;
    }
  }
  if (robust.condition) {
    const auto fails = [&](std::size_t k) {
      return !problem.slots[k][choice[k]].survives_condition;
    };
    if (!meets_sectors(robust.sectors, union_without(fails))) return false;
  }
  return true;
}

// Whether two chosen options' housings overlap.
bool any_clash(const SearchProblem& problem, const std::vector<int>& choice) {
  for (std::size_t j = 0; j < choice.size(); ++j) {
    for (std::size_t k = j + 1; k < choice.size(); ++k) {
      if (choice[j] >= 0 && choice[k] >= 0 &&
          housings_clash(problem.slots[j][choice[j]], problem.slots[k][choice[k]]))
        return true;
    }
  }
  return false;
}

}  // namespace

bool housings_clash(const SearchOption& a, const SearchOption& b) {
  return a.housing && b.housing && geometry::solids_clash(*a.housing, *b.housing);
}

SearchResult brute_force(const SearchProblem& problem) {
  SearchResult result;
  result.cost.total = std::numeric_limits<double>::infinity();
  const std::size_t slots = problem.slots.size();
  std::vector<int> choice(slots, -1);
  while (true) {
    ++result.nodes;
    RigLoad load;
    std::vector<geometry::SectionRaster> sections;
    for (const geometry::RasterGrid& grid : problem.grids) sections.emplace_back(grid);
    for (std::size_t k = 0; k < slots; ++k) {
      if (choice[k] < 0) continue;
      const SearchOption& option = problem.slots[k][choice[k]];
      load.sensor_cost += option.price;
      load.per_sensor_transfer += option.transfer_price;
      load.bandwidth += option.bandwidth;
      load.cpu += option.cpu;
      ++load.sensors;
      for (std::size_t a = 0; a < sections.size(); ++a) sections[a] |= option.section(a);
    }
    const CostBreakdown cost = rig_cost(load, problem.transfer, problem.cpus);
    if (load.sensors > 0 && cost.feasible && cost.total <= result.cost.total + kCostTie) {
      ++result.evaluations;
      bool feasible = true;
      for (const SearchSector& sector : problem.sectors) {
        for (const int a : sector.angles) {
          feasible = feasible && meets(sections[a].complete_share(), sector.min_complete) &&
                     meets(sections[a].floor_share(), sector.min_floor);
        }
      }
      feasible = feasible && survives(problem, choice) && !any_clash(problem, choice);
      const std::vector<double> margins = sector_margins(problem, sections);
      if (feasible && improves(result, cost.total, margins)) {
        result.found = true;
        result.cost = cost;
        result.choice = choice;
        result.margin = smallest_of(margins);
        result.margins = margins;
      }
    }
    // Next assignment, as a mixed-radix counter where -1 is each slot's first digit.
    std::size_t k = 0;
    while (k < slots && ++choice[k] == static_cast<int>(problem.slots[k].size())) choice[k++] = -1;
    if (k == slots) break;
  }
  return result;
}

}  // namespace rigdesign::select
