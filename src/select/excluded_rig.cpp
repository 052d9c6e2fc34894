#include "select/excluded_rig.hpp"

#include <cmath>

#include "select/hardware_limits.hpp"

namespace rigdesign::select {
namespace {

// Thrown from the search's progress callback to end it early (the main search found no rig,
// or the command is over): the only way into a running branch and bound.
struct SearchStopped {};

}  // namespace

CheaperRigSearch::CheaperRigSearch(const SearchProblem& problem) : problem_(problem) {
  search_ = std::async(std::launch::async, [this]() -> std::optional<SearchResult> {
    SearchProblem free_hardware = with_unlimited_hardware(problem_);
    free_hardware.widen_margins = false;  // only its cost and what rules it out are reported
    try {
      return branch_and_bound(free_hardware, {}, [this](const SearchProgress&) {
        if (stop_) throw SearchStopped{};
      });
    } catch (const SearchStopped&) {
      return std::nullopt;
    }
  });
}

CheaperRigSearch::~CheaperRigSearch() {
  stop_ = true;
  if (search_.valid()) search_.wait();
}

std::optional<ExcludedRig> CheaperRigSearch::result(
    const std::vector<std::vector<const CatalogOption*>>& kept, const CostBreakdown& chosen) {
  const std::optional<SearchResult> cheaper = search_.get();
  if (!cheaper || !cheaper->found) return std::nullopt;
  // Its load and price on the real catalog: the options' own per-sensor transfer prices.
  const RigLoad load = load_of(problem_, *cheaper);
  // A rig within a tie of the chosen one's cost is no cheaper.
  if (!(load.sensor_cost < chosen.total - kCostTie)) return std::nullopt;
  ExcludedRig rig;
  for (std::size_t k = 0; k < cheaper->choice.size(); ++k) {
    if (cheaper->choice[k] >= 0) rig.chosen.push_back(kept[k][cheaper->choice[k]]);
  }
  rig.sensor_cost = load.sensor_cost;
  rig.cpu = load.cpu;
  rig.bandwidth = load.bandwidth;
  rig.largest_cpu = largest_capacity(problem_.cpus, rig.largest_cpu_id);
  rig.transfer_bottleneck = transfer_bottleneck(problem_.transfer, rig.transfer_bottleneck_id);
  rig.per_sensor_transfer_missing = !std::isfinite(load.per_sensor_transfer);
  rig.cost = rig_cost(load, problem_.transfer, problem_.cpus);
  rig.cpu_too_small = cheapest_exceeding(problem_.cpus, load.cpu) == nullptr;
  // The transfer alone: with the free, unlimited CPU it still carries nothing.
  rig.transfer_too_small = !rig_cost(load, problem_.transfer, unlimited_capacity()).feasible;
  return rig;
}

}  // namespace rigdesign::select
