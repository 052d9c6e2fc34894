// The proven-optimal search on compressed coverage classes (DESIGN.md section 5, issue 15).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include "rigdesign/select/class_coverage.hpp"
#include "rigdesign/select/search.hpp"
#include "select/robust_bound.hpp"
#include "select/search_rules.hpp"
#include "select/sector_needs.hpp"

namespace rigdesign::select {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();
constexpr long kProgressEvery = 4096;

class BranchAndBound {
 public:
  BranchAndBound(const SearchProblem& problem, const std::vector<std::vector<int>>& excluded,
                 const std::function<void(const SearchProgress&)>& progress)
      : problem_(problem), excluded_(excluded), progress_(progress), classes_(problem) {
    const std::size_t slots = problem.slots.size();
    const std::size_t angles = classes_.angles();
    const std::size_t words = classes_.words();
    needs_ = needs_of(problem.sectors, classes_);
    robust_needs_ = needs_of(problem.robustness.sectors, classes_);
    std::vector<bool> searched(angles, false);
    for (const Need& need : needs_) searched[need.angle] = true;
    for (const Need& need : robust_needs_) searched[need.angle] = true;
    for (const geometry::RasterGrid& grid : problem.grids)
      result_.raster_cells += static_cast<long>(grid.columns) * (grid.rows + 1);
    result_.coverage_classes = static_cast<long>(classes_.classes());

    find_clashes();
    // Options to try per slot, cheapest first (good incumbents early make the cost bound
    // bite), without the dominated ones; and the angles each one changes the search state at.
    order_.resize(slots);
    searched_span_.resize(slots);
    for (std::size_t k = 0; k < slots; ++k) {
      searched_span_[k].resize(problem.slots[k].size());
      for (std::size_t o = 0; o < problem.slots[k].size(); ++o) {
        for (const int a : classes_.span(k, o))
          if (searched[a]) searched_span_[k][o].push_back(a);
        if (excluded.empty() && dominated(k, o)) {
          ++result_.dominated;
          continue;
        }
        order_[k].push_back(static_cast<int>(o));
      }
      std::stable_sort(order_[k].begin(), order_[k].end(), [&](int x, int y) {
        return problem.slots[k][x].price < problem.slots[k][y].price;
      });
    }
    robust_.emplace(problem, classes_, robust_needs_, order_);
    // rest_[k]: the union of every option of slots k.. (the coverage bound), its counts, and
    // per angle the least any of those options covering a cell (floor column) there adds.
    rest_.assign(slots + 1, std::vector<std::uint64_t>(words, 0));
    rest_counts_.assign(slots + 1, std::vector<CellCounts>(angles));
    cheapest_cells_.assign(slots + 1, std::vector<LeastAddition>(angles, LeastAddition::none()));
    cheapest_floor_.assign(slots + 1, std::vector<LeastAddition>(angles, LeastAddition::none()));
    for (std::size_t k = slots; k-- > 0;) {
      rest_[k] = rest_[k + 1];
      cheapest_cells_[k] = cheapest_cells_[k + 1];
      cheapest_floor_[k] = cheapest_floor_[k + 1];
      for (const int o : order_[k]) {
        const std::uint64_t* bits = classes_.bits(k, o);
        for (std::size_t w = 0; w < words; ++w) rest_[k][w] |= bits[w];
        for (const int a : searched_span_[k][o]) {
          const CellCounts alone = classes_.count(a, bits);
          const LeastAddition adds = LeastAddition::of(problem.slots[k][o]);
          if (alone.cells > 0) cheapest_cells_[k][a] = cheapest_cells_[k][a].least(adds);
          if (alone.floor > 0) cheapest_floor_[k][a] = cheapest_floor_[k][a].least(adds);
        }
      }
      for (std::size_t a = 0; a < angles; ++a)
        rest_counts_[k][a] = classes_.count(a, rest_[k].data());
    }
    union_.assign(words, 0);
    scratch_.assign(words, 0);
    unmet_.resize(slots + 1);
    angle_bits_.resize(slots);
    for (std::size_t k = 0; k < slots; ++k) {
      for (std::size_t o = 0; o < problem.slots[k].size(); ++o) {
        std::vector<std::uint64_t> bits((angles + 63) / 64, 0);
        for (const int a : classes_.span(k, o))
          bits[static_cast<std::size_t>(a) / 64] |= std::uint64_t{1} << (a % 64);
        angle_bits_[k].push_back(std::move(bits));
      }
    }
    counts_.assign(angles, {});
    choice_.assign(slots, -1);
    position_.assign(slots, 0);
    result_.cost.total = problem.cost_below;
  }

  SearchResult run() {
    visit(0, RigLoad{}, false);
    return result_;
  }

 private:
  // Which options of different slots have housings that overlap (issue 52 item 2): a rig
  // never holds both. Options far apart (bounding spheres apart) are not tested.
  void find_clashes() {
    const auto& slots = problem_.slots;
    clashes_.resize(slots.size());
    clashing_.resize(slots.size());
    std::vector<std::vector<std::pair<model::Vec3, double>>> spheres(slots.size());
    for (std::size_t k = 0; k < slots.size(); ++k) {
      clashes_[k].resize(slots[k].size());
      clashing_[k].assign(slots[k].size(), false);
      for (const SearchOption& option : slots[k]) {
        model::Vec3 centre = model::Vec3::Zero();
        double radius = -1.0;  // no housing
        if (option.housing) {
          for (const model::Vec3& p : option.housing->corners) centre += p;
          centre /= static_cast<double>(option.housing->corners.size());
          radius = 0.0;
          for (const model::Vec3& p : option.housing->corners)
            radius = std::max(radius, (p - centre).norm());
        }
        spheres[k].emplace_back(centre, radius);
      }
    }
    for (std::size_t k = 0; k < slots.size(); ++k) {
      for (std::size_t j = 0; j < k; ++j) {
        for (std::size_t o = 0; o < slots[k].size(); ++o) {
          for (std::size_t p = 0; p < slots[j].size(); ++p) {
            const auto& [a, ra] = spheres[k][o];
            const auto& [b, rb] = spheres[j][p];
            if (ra < 0 || rb < 0 || (a - b).norm() > ra + rb) continue;
            if (!housings_clash(slots[k][o], slots[j][p])) continue;
            clashes_[k][o].emplace_back(static_cast<int>(j), static_cast<int>(p));
            clashing_[k][o] = true;
            clashing_[j][p] = true;
            ++result_.housing_clashes;
          }
        }
      }
    }
  }

  // Whether option o of slot k overlaps a housing already chosen.
  bool clashes_with_choice(std::size_t k, int o) const {
    const auto& against = clashes_[k][static_cast<std::size_t>(o)];
    return std::any_of(against.begin(), against.end(), [&](const std::pair<int, int>& other) {
      return choice_[static_cast<std::size_t>(other.first)] == other.second;
    });
  }

  // Whether another option of slot k makes option o pointless: no dearer in price, its own
  // transfer components, bandwidth and CPU, surviving the condition if o does, covering every class
  // o covers; identical options keep the first.
  bool dominated(std::size_t k, std::size_t o) const {
    const SearchOption& mine = problem_.slots[k][o];
    const std::uint64_t* my_bits = classes_.bits(k, o);
    for (std::size_t p = 0; p < problem_.slots[k].size(); ++p) {
      if (p == o) continue;
      const SearchOption& other = problem_.slots[k][p];
      // An option whose housing rules others out cannot stand in for one that does not.
      if (clashing_[k][p]) continue;
      if (other.price > mine.price || other.transfer_price > mine.transfer_price ||
          other.bandwidth > mine.bandwidth || other.cpu > mine.cpu ||
          (mine.survives_condition && !other.survives_condition)) {
        continue;
      }
      const std::uint64_t* other_bits = classes_.bits(k, p);
      bool covers = true;
      for (std::size_t w = 0; w < classes_.words() && covers; ++w)
        covers = (my_bits[w] & ~other_bits[w]) == 0;
      if (!covers) continue;
      const bool identical = other.price == mine.price &&
                             other.transfer_price == mine.transfer_price &&
                             other.bandwidth == mine.bandwidth && other.cpu == mine.cpu &&
                             other.survives_condition == mine.survives_condition &&
                             classes_.span(k, p) == classes_.span(k, o) &&
                             std::equal(my_bits, my_bits + classes_.words(), other_bits);
      if (!identical || p < o) return true;
    }
    return false;
  }

  // Adds option o of slot k to the union at the searched angles, saving what it changes.
  // The saved words are a stack that only grows to the deepest path's size: no per-node
  // allocation, no zero-fill.
  void add(std::size_t k, int o) {
    robust_->add(k, o);
    const std::uint64_t* bits = classes_.bits(k, o);
    for (const int a : searched_span_[k][o]) {
      const std::size_t angle = static_cast<std::size_t>(a);
      saved_counts_.push_back(counts_[angle]);
      const std::size_t words = classes_.end(angle) - classes_.begin(angle);
      if (saved_words_.size() < saved_top_ + words) saved_words_.resize(2 * (saved_top_ + words));
      const CellCounts gain =
          classes_.merge(angle, bits, union_.data(), saved_words_.data() + saved_top_);
      saved_top_ += words;
      counts_[angle].cells += gain.cells;
      counts_[angle].floor += gain.floor;
    }
  }

  void remove(std::size_t k, int o) {
    robust_->remove(k, o);
    const std::vector<int>& span = searched_span_[k][o];
    for (auto it = span.rbegin(); it != span.rend(); ++it) {
      const std::size_t a = static_cast<std::size_t>(*it);
      counts_[a] = saved_counts_.back();
      saved_counts_.pop_back();
      const std::size_t words = classes_.end(a) - classes_.begin(a);
      saved_top_ -= words;
      std::copy_n(saved_words_.begin() + static_cast<long>(saved_top_), words,
                  union_.begin() + static_cast<long>(classes_.begin(a)));
    }
  }

  // Counts at `angle` of the chosen options except those `dropped` says failed.
  template <typename Dropped>
  CellCounts counts_without(std::size_t angle, Dropped dropped) {
    std::fill(scratch_.begin() + static_cast<long>(classes_.begin(angle)),
              scratch_.begin() + static_cast<long>(classes_.end(angle)), 0);
    for (std::size_t k = 0; k < choice_.size(); ++k) {
      if (choice_[k] < 0 || dropped(k)) continue;
      const std::uint64_t* bits = classes_.bits(k, choice_[k]);
      for (std::size_t w = classes_.begin(angle); w < classes_.end(angle); ++w)
        scratch_[w] |= bits[w];
    }
    return classes_.count(angle, scratch_.data());
  }

  template <typename Dropped>
  bool meets_robust_needs(Dropped dropped) {
    return std::all_of(robust_needs_.begin(), robust_needs_.end(), [&](const Need& need) {
      return met(counts_without(need.angle, dropped), need);
    });
  }

  // Whether the chosen rig still meets the robustness sectors after every failure the
  // problem asks it to survive: each chosen sensor alone, and every sensor that does not
  // survive the condition at once.
  bool survives() {
    const Robustness& robust = problem_.robustness;
    if (robust.single_failure) {
      for (std::size_t j = 0; j < choice_.size(); ++j) {
        if (choice_[j] >= 0 && !meets_robust_needs([&](std::size_t k) { return k == j; }))
          return false;
      }
    }
    if (robust.condition) {
      return meets_robust_needs(
          [&](std::size_t k) { return !problem_.slots[k][choice_[k]].survives_condition; });
    }
    return true;
  }

  // A need's margin with `have` covered: the smaller of SC complete's and floor's.
  double margin_at(const Need& need, const CellCounts& have) const {
    const CellCounts total = classes_.total(need.angle);
    return std::min(
        static_cast<double>(have.cells) / static_cast<double>(total.cells) - need.min_complete,
        static_cast<double>(have.floor) / static_cast<double>(total.floor) - need.min_floor);
  }

  // Each sector's smallest margin over its angles, smallest first; `tightest` gets, per
  // sector, the need where it is smallest.
  std::vector<double> sector_margins(std::vector<std::size_t>* tightest = nullptr) const {
    std::vector<double> margins(problem_.sectors.size(), kNoBound);
    if (tightest != nullptr) tightest->assign(problem_.sectors.size(), needs_.size());
    for (std::size_t i = 0; i < needs_.size(); ++i) {
      const double margin = margin_at(needs_[i], counts_[needs_[i].angle]);
      if (margin < margins[needs_[i].sector]) {
        margins[needs_[i].sector] = margin;
        if (tightest != nullptr) (*tightest)[needs_[i].sector] = i;
      }
    }
    std::sort(margins.begin(), margins.end());
    return margins;
  }

  // Margins of the chosen sensors plus every option of slots depth.. at `need`: no
  // completion's margin there is larger (a margin only grows with coverage).
  double margin_bound(std::size_t depth, const Need& need) const {
    CellCounts reach = counts_[need.angle];
    const CellCounts gain = classes_.count_new(need.angle, rest_[depth].data(), union_.data());
    reach.cells += gain.cells;
    reach.floor += gain.floor;
    return margin_at(need, reach);
  }

  // Whether some completion of this node may beat the incumbent's margins (leximin). A
  // sector's smallest margin is at most its bound at any one of its angles; sorted, the
  // sectors' bounds are at least any completion's sorted margins element by element, so if
  // they do not beat the incumbent no completion does. First at the incumbent's tightest
  // angle per sector (cheap, usually decisive), then at every angle.
  bool may_widen_margins(std::size_t depth) const {
    std::vector<double> bound(problem_.sectors.size(), kNoBound);
    const auto beats_incumbent = [&] {
      std::vector<double> sorted = bound;
      std::sort(sorted.begin(), sorted.end());
      return std::lexicographical_compare(result_.margins.begin(), result_.margins.end(),
                                          sorted.begin(), sorted.end());
    };
    for (std::size_t sector = 0; sector < tightest_.size(); ++sector) {
      if (tightest_[sector] < needs_.size())
        bound[sector] = margin_bound(depth, needs_[tightest_[sector]]);
    }
    if (!beats_incumbent()) return false;
    for (const Need& need : needs_)
      bound[need.sector] = std::min(bound[need.sector], margin_bound(depth, need));
    return beats_incumbent();
  }

  // SC complete averaged over every angle of the problem (the Pareto plot's axis).
  double mean_complete() {
    double sum = 0.0;
    for (std::size_t a = 0; a < classes_.angles(); ++a) {
      const CellCounts have = counts_without(a, [](std::size_t) { return false; });
      sum += static_cast<double>(have.cells) / static_cast<double>(classes_.total(a).cells);
    }
    return classes_.angles() == 0 ? 0.0 : sum / static_cast<double>(classes_.angles());
  }

  // A rig whose sensors are chosen (the rest nothing): record it if it meets every sector
  // threshold and survives what it must, and say whether it does.
  bool evaluate(const RigLoad& load, double cost) {
    ++result_.evaluations;
    const bool feasible =
        std::all_of(needs_.begin(), needs_.end(),
                    [&](const Need& need) { return met(counts_[need.angle], need); }) &&
        std::find(excluded_.begin(), excluded_.end(), choice_) == excluded_.end() && survives();
    if (!feasible) return false;
    result_.explored.push_back({cost, mean_complete(), true});
    std::vector<std::size_t> tightest;
    std::vector<double> margins = sector_margins(&tightest);
    if (improves(result_, cost, margins)) {
      tightest_ = std::move(tightest);
      result_.found = true;
      result_.cost = rig_cost(load, problem_.transfer, problem_.cpus);
      result_.choice = choice_;
      result_.margin = smallest_of(margins);
      result_.margins = std::move(margins);
    }
    return true;
  }

  // Whether some completion of this node may meet every threshold for no more than the
  // incumbent: the coverage bound per needed angle, then the cost bound (this node's load
  // plus, part by part, the least an option of an undecided slot covering anything at an
  // uncovered angle adds, at the angle where that is largest: any completion buys at least
  // one such option per angle; the robustness bound's additions likewise).
  bool promising(std::size_t depth, const RigLoad& load) const {
    LeastAddition extra;
    for (const Need& need : needs_) {
      if (!reachable(depth, need)) return false;
      extra = extra.most(still_adds(depth, need));
    }
    // A surviving rig meets the after-failure thresholds before any failure too.
    for (const Need& need : robust_->needs())
      if (!reachable(depth, need)) return false;
    if (!robust_->may_survive(depth, union_.data(), counts_)) return false;
    extra = extra.most(robust_->least_addition(depth));
    if (!extra.possible()) return false;
    RigLoad bound = load;
    bound.sensor_cost += extra.price;
    bound.bandwidth += extra.bandwidth;
    bound.cpu += extra.cpu;
    const double least_cost = total_cost(bound, problem_.transfer, problem_.cpus);
    // No catalog CPU or transfer item carries the least load a completion adds.
    if (!std::isfinite(least_cost) || least_cost > result_.cost.total + kCostTie) return false;
    // No completion is cheaper than the incumbent: only wider margins can win.
    return !result_.found || least_cost < result_.cost.total - kCostTie ||
           (problem_.widen_margins && may_widen_margins(depth));
  }

  // Whether the chosen sensors and every option of slots depth.. together meet `need`.
  bool reachable(std::size_t depth, const Need& need) const {
    const CellCounts& have = counts_[need.angle];
    if (met(have, need)) return true;
    const CellCounts& rest = rest_counts_[depth][need.angle];
    if (have.cells + rest.cells < need.cells || have.floor + rest.floor < need.floor) return false;
    return classes_.reaches(need.angle, rest_[depth].data(), union_.data(), have,
                            {need.cells, need.floor});
  }

  // What `need` still asks a completion from slots `depth`.. to add: nothing once it is met.
  LeastAddition still_adds(std::size_t depth, const Need& need) const {
    const CellCounts& have = counts_[need.angle];
    LeastAddition adds;
    if (have.cells < need.cells) adds = adds.most(cheapest_cells_[depth][need.angle]);
    if (have.floor < need.floor) adds = adds.most(cheapest_floor_[depth][need.angle]);
    return adds;
  }

  // The needs still unmet (plain, and robustness needs short of covering sensors), each with
  // what it asks of slots `next`.., dearest first.
  void unmet_needs(std::size_t next, std::vector<UnmetNeed>& unmet) const {
    unmet.clear();
    for (const Need& need : needs_) {
      if (!met(counts_[need.angle], need)) unmet.push_back({need.angle, still_adds(next, need)});
    }
    robust_->append_unmet(next, unmet);
    std::sort(unmet.begin(), unmet.end(), [](const UnmetNeed& x, const UnmetNeed& y) {
      return x.addition.price > y.addition.price;
    });
  }

  // Whether adding option o of slot `depth` cannot lead to a rig for no more than the
  // incumbent, decided before adding it: o covers nothing at the dearest unmet need it does
  // not reach, so every completion through o still buys that need's least addition (what
  // promising() would find at the child, without merging o's coverage first).
  bool cut_before_adding(std::size_t depth, int o, const RigLoad& load,
                         const std::vector<UnmetNeed>& unmet) const {
    if (unmet.empty() || !result_.found) return false;
    const std::vector<std::uint64_t>& reaches = angle_bits_[depth][static_cast<std::size_t>(o)];
    const auto missed = std::find_if(unmet.begin(), unmet.end(), [&](const UnmetNeed& d) {
      return ((reaches[d.angle / 64] >> (d.angle % 64)) & 1U) == 0;
    });
    if (missed == unmet.end()) return false;
    const SearchOption& option = problem_.slots[depth][o];
    RigLoad bound = load;
    bound.sensor_cost += option.price + missed->addition.price;
    bound.per_sensor_transfer += option.transfer_price;
    bound.bandwidth += option.bandwidth + missed->addition.bandwidth;
    bound.cpu += option.cpu + missed->addition.cpu;
    ++bound.sensors;
    const double least_cost = total_cost(bound, problem_.transfer, problem_.cpus);
    return !std::isfinite(least_cost) || least_cost > result_.cost.total + kCostTie;
  }

  void report_progress(std::size_t depth) {
    if (!progress_) return;
    double fraction = 0.0;
    double width = 1.0;
    for (std::size_t d = 0; d < depth && d < position_.size(); ++d) {
      const double branches = static_cast<double>(order_[d].size() + 1);
      fraction += width * position_[d] / branches;
      width /= branches;
    }
    progress_({result_.nodes, fraction});
  }

  void visit(std::size_t depth, const RigLoad& load, bool just_added) {
    if (++result_.nodes % kProgressEvery == 0) report_progress(depth);
    const double cost = total_cost(load, problem_.transfer, problem_.cpus);
    // No transfer item or CPU carries this load: none carries a larger one either.
    // An equal cost is explored too: it may hold a rig with a larger margin.
    if (!std::isfinite(cost) || cost > result_.cost.total + kCostTie) return;
    // Without the margins' tie-break an equal cost is no better than the incumbent.
    if (!problem_.widen_margins && result_.found && cost > result_.cost.total - kCostTie) return;
    // A feasible rig needs nothing more: any addition costs more.
    if (just_added && evaluate(load, cost)) return;
    if (depth == problem_.slots.size() || !promising(depth, load)) return;
    std::vector<UnmetNeed>& unmet = unmet_[depth];
    unmet_needs(depth + 1, unmet);
    for (std::size_t i = 0; i < order_[depth].size(); ++i) {
      const int o = order_[depth][i];
      const SearchOption& option = problem_.slots[depth][o];
      position_[depth] = static_cast<int>(i);
      if (clashes_with_choice(depth, o)) continue;
      if (cut_before_adding(depth, o, load, unmet)) continue;
      choice_[depth] = o;
      add(depth, o);
      RigLoad next = load;
      next.sensor_cost += option.price;
      next.per_sensor_transfer += option.transfer_price;
      next.bandwidth += option.bandwidth;
      next.cpu += option.cpu;
      ++next.sensors;
      visit(depth + 1, next, true);
      remove(depth, o);
    }
    position_[depth] = static_cast<int>(order_[depth].size());
    choice_[depth] = -1;
    visit(depth + 1, load, false);
  }

  const SearchProblem& problem_;
  const std::vector<std::vector<int>>& excluded_;
  const std::function<void(const SearchProgress&)>& progress_;
  const ClassCoverage classes_;
  std::vector<Need> needs_;
  std::vector<Need> robust_needs_;
  std::optional<RobustBound> robust_;
  std::vector<std::vector<int>> order_;
  std::vector<std::vector<std::vector<int>>> searched_span_;
  std::vector<std::vector<std::uint64_t>> rest_;
  std::vector<std::vector<CellCounts>> rest_counts_;
  std::vector<std::vector<LeastAddition>> cheapest_cells_;
  std::vector<std::vector<LeastAddition>> cheapest_floor_;
  std::vector<std::uint64_t> union_;
  std::vector<CellCounts> counts_;
  std::vector<std::uint64_t> saved_words_;  // a stack: [0, saved_top_) in use
  std::size_t saved_top_ = 0;
  std::vector<CellCounts> saved_counts_;
  std::vector<std::uint64_t> scratch_;
  std::vector<int> choice_;
  std::vector<int> position_;
  std::vector<std::size_t> tightest_;  // the incumbent's tightest need per sector
  std::vector<std::vector<std::vector<std::uint64_t>>>
      angle_bits_;                             // per option: its span's angles
  std::vector<std::vector<UnmetNeed>> unmet_;  // per depth: scratch
  // Per slot, per option: the (slot, option) pairs of earlier slots whose housings overlap
  // it, and whether it overlaps any option at all.
  std::vector<std::vector<std::vector<std::pair<int, int>>>> clashes_;
  std::vector<std::vector<bool>> clashing_;
  SearchResult result_;
};

}  // namespace

SearchResult branch_and_bound(const SearchProblem& problem,
                              const std::vector<std::vector<int>>& excluded,
                              const std::function<void(const SearchProgress&)>& progress) {
  return BranchAndBound(problem, excluded, progress).run();
}

}  // namespace rigdesign::select
