#include "rigdesign/select/search.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace rigdesign::select {
namespace {

bool meets(double share, double threshold) {
  return share >= threshold - kThresholdSlack;
}

// The smallest margin of `sections` over the sectors' angles (+inf without sectors).
double smallest_margin(const SearchProblem& problem,
                       const std::vector<geometry::SectionRaster>& sections) {
  double margin = std::numeric_limits<double>::infinity();
  for (const SearchSector& sector : problem.sectors) {
    for (const int a : sector.angles) {
      margin = std::min({margin, sections[a].complete_share() - sector.min_complete,
                         sections[a].floor_share() - sector.min_floor});
    }
  }
  return margin;
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
        for (const int a : sector.angles) sections[a] |= option.sections[a];
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

// Whether a feasible rig of `cost` and `margin` beats the best so far: cheaper, or as cheap
// with a larger smallest margin. Counts the ties at the best cost.
bool improves(SearchResult& best, double cost, double margin) {
  if (!best.found || cost < best.cost.total - kCostTie) {
    best.ties = 1;
    return true;
  }
  if (cost > best.cost.total + kCostTie) return false;
  ++best.ties;
  return margin > best.margin;
}

class BranchAndBound {
 public:
  BranchAndBound(const SearchProblem& problem, const std::vector<std::vector<int>>& excluded,
                 const std::function<void(long)>& progress)
      : problem_(problem), excluded_(excluded), progress_(progress) {
    const std::size_t slots = problem.slots.size();
    const std::size_t angles = problem.grids.size();
    // suffix_[k][a]: the union of every option of slots k.. at angle a (the coverage bound).
    suffix_.assign(slots + 1, {});
    for (std::size_t a = 0; a < angles; ++a) suffix_[slots].emplace_back(problem.grids[a]);
    for (std::size_t k = slots; k-- > 0;) {
      suffix_[k] = suffix_[k + 1];
      for (const SearchOption& option : problem.slots[k]) {
        for (std::size_t a = 0; a < angles; ++a) suffix_[k][a] |= option.sections[a];
      }
    }
    // union_[k]: the union of the options chosen for slots before k.
    union_.assign(slots + 1, suffix_[slots]);
    // Cheaper options first: good incumbents early make the cost bound bite.
    order_.resize(slots);
    for (std::size_t k = 0; k < slots; ++k) {
      order_[k].resize(problem.slots[k].size());
      std::iota(order_[k].begin(), order_[k].end(), 0);
      std::stable_sort(order_[k].begin(), order_[k].end(), [&](int x, int y) {
        return problem.slots[k][x].price < problem.slots[k][y].price;
      });
    }
    choice_.assign(slots, -1);
    result_.cost.total = std::numeric_limits<double>::infinity();
  }

  SearchResult run() {
    visit(0, RigLoad{}, false);
    return result_;
  }

 private:
  // A rig whose sensors are chosen (the rest nothing): record it, and say whether it meets
  // every sector threshold.
  bool evaluate(std::size_t depth, const CostBreakdown& cost) {
    ++result_.evaluations;
    const std::vector<geometry::SectionRaster>& sections = union_[depth];
    bool feasible = std::find(excluded_.begin(), excluded_.end(), choice_) == excluded_.end();
    for (const SearchSector& sector : problem_.sectors) {
      for (const int a : sector.angles) {
        if (!feasible) break;
        feasible = meets(sections[a].complete_share(), sector.min_complete) &&
                   meets(sections[a].floor_share(), sector.min_floor);
      }
    }
    feasible = feasible && survives(problem_, choice_);
    double mean = 0.0;
    for (const geometry::SectionRaster& section : sections) mean += section.complete_share();
    const double angles = static_cast<double>(sections.size());
    result_.explored.push_back({cost.total, sections.empty() ? 0.0 : mean / angles, feasible});
    if (feasible) {
      const double margin = smallest_margin(problem_, sections);
      if (improves(result_, cost.total, margin)) {
        result_.found = true;
        result_.cost = cost;
        result_.choice = choice_;
        result_.margin = margin;
      }
    }
    return feasible;
  }

  // The best coverage any completion of this node can reach still meets every threshold.
  bool may_meet(std::size_t depth) const {
    for (const SearchSector& sector : problem_.sectors) {
      for (const int a : sector.angles) {
        const geometry::SectionRaster& chosen = union_[depth][a];
        const geometry::SectionRaster& rest = suffix_[depth][a];
        if (!meets(chosen.complete_share_with(rest), sector.min_complete) ||
            !meets(chosen.floor_share_with(rest), sector.min_floor)) {
          return false;
        }
      }
    }
    return true;
  }

  void visit(std::size_t depth, const RigLoad& load, bool just_added) {
    if (++result_.nodes % 4096 == 0 && progress_) progress_(result_.nodes);
    const CostBreakdown cost = rig_cost(load, problem_.transfer, problem_.cpus);
    // No transfer item or CPU carries this load: none carries a larger one either.
    // An equal cost is explored too: it may hold a rig with a larger margin.
    if (!cost.feasible || cost.total > result_.cost.total + kCostTie) return;
    // A feasible rig needs nothing more: any addition costs more.
    if (just_added && evaluate(depth, cost)) return;
    if (depth == problem_.slots.size() || !may_meet(depth)) return;
    for (const int option_index : order_[depth]) {
      const SearchOption& option = problem_.slots[depth][option_index];
      choice_[depth] = option_index;
      union_[depth + 1] = union_[depth];
      for (std::size_t a = 0; a < union_[depth + 1].size(); ++a) {
        union_[depth + 1][a] |= option.sections[a];
      }
      RigLoad next = load;
      next.sensor_cost += option.price;
      next.bandwidth += option.bandwidth;
      next.cpu += option.cpu;
      ++next.sensors;
      visit(depth + 1, next, true);
    }
    choice_[depth] = -1;
    union_[depth + 1] = union_[depth];
    visit(depth + 1, load, false);
  }

  const SearchProblem& problem_;
  const std::vector<std::vector<int>>& excluded_;
  const std::function<void(long)>& progress_;
  std::vector<std::vector<geometry::SectionRaster>> suffix_;
  std::vector<std::vector<geometry::SectionRaster>> union_;
  std::vector<std::vector<int>> order_;
  std::vector<int> choice_;
  SearchResult result_;
};

}  // namespace

SearchResult branch_and_bound(const SearchProblem& problem,
                              const std::vector<std::vector<int>>& excluded,
                              const std::function<void(long)>& progress) {
  return BranchAndBound(problem, excluded, progress).run();
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
      load.bandwidth += option.bandwidth;
      load.cpu += option.cpu;
      ++load.sensors;
      for (std::size_t a = 0; a < sections.size(); ++a) sections[a] |= option.sections[a];
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
      feasible = feasible && survives(problem, choice);
      const double margin = smallest_margin(problem, sections);
      if (feasible && improves(result, cost.total, margin)) {
        result.found = true;
        result.cost = cost;
        result.choice = choice;
        result.margin = margin;
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
