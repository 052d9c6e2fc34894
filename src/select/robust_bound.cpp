#include "select/robust_bound.hpp"

#include <algorithm>
#include <limits>

namespace rigdesign::select {
RobustBound::RobustBound(const SearchProblem& problem, const ClassCoverage& classes,
                         std::vector<Need> needs, const std::vector<std::vector<int>>& order)
    : problem_(problem), classes_(classes), needs_(std::move(needs)) {
  const std::size_t slots = problem.slots.size();
  const Robustness& robust = problem.robustness;
  if (!robust.any()) needs_.clear();
  // Only angles where a failure must leave something constrain anything.
  std::erase_if(needs_, [](const Need& need) { return need.cells == 0 && need.floor == 0; });
  const std::size_t count = needs_.size();
  touches_.resize(slots);
  slot_needs_.resize(slots);
  // Per slot and need: the least an option covering cells (floor) adds, and a surviving one.
  std::vector<std::vector<LeastAddition>> slot_cells(
      slots, std::vector<LeastAddition>(count, LeastAddition::none()));
  std::vector<std::vector<LeastAddition>> slot_floor = slot_cells;
  std::vector<std::vector<LeastAddition>> slot_surviving_cells = slot_cells;
  std::vector<std::vector<LeastAddition>> slot_surviving_floor = slot_cells;
  for (std::size_t k = 0; k < slots; ++k) {
    touches_[k].resize(problem.slots[k].size());
    for (const int o : order[k]) {
      const SearchOption& option = problem.slots[k][o];
      const LeastAddition adds = LeastAddition::of(option);
      const std::vector<int>& span = classes.span(k, o);
      for (std::size_t i = 0; i < count; ++i) {
        if (!std::binary_search(span.begin(), span.end(), static_cast<int>(needs_[i].angle)))
          continue;
        const CellCounts alone = classes.count(needs_[i].angle, classes.bits(k, o));
        const Touch touch{i, alone.cells > 0, alone.floor > 0};
        if (!touch.cells && !touch.floor) continue;
        touches_[k][o].push_back(touch);
        if (slot_needs_[k].empty() || slot_needs_[k].back() != i) slot_needs_[k].push_back(i);
        if (touch.cells) slot_cells[k][i] = slot_cells[k][i].least(adds);
        if (touch.floor) slot_floor[k][i] = slot_floor[k][i].least(adds);
        if (option.survives_condition && touch.cells)
          slot_surviving_cells[k][i] = slot_surviving_cells[k][i].least(adds);
        if (option.survives_condition && touch.floor)
          slot_surviving_floor[k][i] = slot_surviving_floor[k][i].least(adds);
      }
    }
    std::sort(slot_needs_[k].begin(), slot_needs_[k].end());
    slot_needs_[k].erase(std::unique(slot_needs_[k].begin(), slot_needs_[k].end()),
                         slot_needs_[k].end());
  }
  // From the last slot up: one option, two of distinct slots (a slot adds at least its
  // least), and one surviving option of slots >= depth; part by part, each the least.
  const auto cheapest_from = [&](const std::vector<std::vector<LeastAddition>>& per_slot,
                                 const std::vector<std::vector<LeastAddition>>& surviving) {
    std::vector<std::vector<Cheapest>> table(slots + 1, std::vector<Cheapest>(count));
    for (std::size_t k = slots; k-- > 0;) {
      for (std::size_t i = 0; i < count; ++i) {
        Cheapest c = table[k + 1][i];
        const LeastAddition& here = per_slot[k][i];
        c.two = c.two.least(c.one.plus(here));
        c.one = c.one.least(here);
        c.surviving = c.surviving.least(surviving[k][i]);
        table[k][i] = c;
      }
    }
    return table;
  };
  cheapest_cells_ = cheapest_from(slot_cells, slot_surviving_cells);
  cheapest_floor_ = cheapest_from(slot_floor, slot_surviving_floor);
  coverers_cells_.assign(count, 0);
  coverers_floor_.assign(count, 0);
  surviving_cells_.assign(count, 0);
  surviving_floor_.assign(count, 0);
  if (!robust.single_failure || count == 0) return;
  const std::size_t words = classes.words();
  rest_without_.resize(slots + 1);
  rest_without_counts_.resize(slots + 1);
  for (std::size_t j = 0; j < slots; ++j) {
    // The union of slots depth.. except j, for every depth <= j, built from the last slot up.
    std::vector<std::uint64_t> rest(words, 0);
    for (std::size_t depth = slots; depth-- > 0;) {
      if (depth != j) {
        for (const int o : order[depth]) {
          const std::uint64_t* bits = classes.bits(depth, o);
          for (std::size_t w = 0; w < words; ++w) rest[w] |= bits[w];
        }
      }
      if (depth > j) continue;
      rest_without_[depth].resize(slots);
      rest_without_counts_[depth].resize(slots);
      rest_without_[depth][j] = rest;
      for (const Need& need : needs_)
        rest_without_counts_[depth][j].push_back(classes.count(need.angle, rest.data()));
    }
  }
}

void RobustBound::add(std::size_t slot, int option) {
  const bool survives = problem_.slots[slot][option].survives_condition;
  for (const Touch& touch : touches_[slot][option]) {
    coverers_cells_[touch.need] += touch.cells;
    coverers_floor_[touch.need] += touch.floor;
    surviving_cells_[touch.need] += touch.cells && survives;
    surviving_floor_[touch.need] += touch.floor && survives;
  }
}

void RobustBound::remove(std::size_t slot, int option) {
  const bool survives = problem_.slots[slot][option].survives_condition;
  for (const Touch& touch : touches_[slot][option]) {
    coverers_cells_[touch.need] -= touch.cells;
    coverers_floor_[touch.need] -= touch.floor;
    surviving_cells_[touch.need] -= touch.cells && survives;
    surviving_floor_[touch.need] -= touch.floor && survives;
  }
}

bool RobustBound::may_survive(std::size_t depth, const std::uint64_t* chosen,
                              const std::vector<CellCounts>& counts) const {
  if (rest_without_.empty()) return true;
  for (std::size_t j = depth; j < problem_.slots.size(); ++j) {
    for (const std::size_t i : slot_needs_[j]) {
      const Need& need = needs_[i];
      const CellCounts& have = counts[need.angle];
      if (met(have, need)) continue;
      const CellCounts& rest = rest_without_counts_[depth][j][i];
      if (have.cells + rest.cells < need.cells || have.floor + rest.floor < need.floor)
        return false;
      if (!classes_.reaches(need.angle, rest_without_[depth][j].data(), chosen, have,
                            {need.cells, need.floor}))
        return false;
    }
  }
  return true;
}

LeastAddition RobustBound::extra_for(std::int64_t needed, int coverers, int surviving,
                                     const Cheapest& cheapest) const {
  LeastAddition extra;
  if (needed == 0) return extra;
  if (problem_.robustness.single_failure && coverers < 2)
    extra = coverers == 0 ? cheapest.two : cheapest.one;
  if (problem_.robustness.condition && surviving == 0) extra = extra.most(cheapest.surviving);
  return extra;
}

LeastAddition RobustBound::need_extra(std::size_t depth, std::size_t i) const {
  return extra_for(needs_[i].cells, coverers_cells_[i], surviving_cells_[i],
                   cheapest_cells_[depth][i])
      .most(extra_for(needs_[i].floor, coverers_floor_[i], surviving_floor_[i],
                      cheapest_floor_[depth][i]));
}

LeastAddition RobustBound::least_addition(std::size_t depth) const {
  LeastAddition extra;
  for (std::size_t i = 0; i < needs_.size(); ++i) extra = extra.most(need_extra(depth, i));
  return extra;
}

void RobustBound::append_unmet(std::size_t depth, std::vector<UnmetNeed>& unmet) const {
  for (std::size_t i = 0; i < needs_.size(); ++i) {
    const LeastAddition extra = need_extra(depth, i);
    if (extra.price > 0 || extra.bandwidth > 0 || extra.cpu > 0 || !extra.possible())
      unmet.push_back({needs_[i].angle, extra});
  }
}

}  // namespace rigdesign::select
