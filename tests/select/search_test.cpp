#include "rigdesign/select/search.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "rigdesign/select/cost_model.hpp"

using namespace rigdesign;

TEST_CASE("cost model: the cheapest transfer and CPU whose capacity exceeds the load") {
  const std::vector<model::PricedCapacity> transfer = {{"onboard", 1.0e9, 0, {}, {}},
                                                       {"card", 4.0e9, 80, {}, {}}};
  const std::vector<model::PricedCapacity> cpus = {
      {"small", 2.0, 300, {}, {}}, {"big", 8.0, 900, {}, {}}, {"mid", 4.0, 500, {}, {}}};
  // 100 MB/s = 0.8 Gbit/s fits the onboard link; 2.5 cores need the 4-core CPU.
  select::CostBreakdown cost = select::rig_cost({1000.0, 100e6, 2.5, 2}, transfer, cpus);
  CHECK(cost.feasible);
  CHECK(cost.transfer_id == "onboard");
  CHECK(cost.cpu_id == "mid");
  CHECK(cost.total == 1000.0 + 0.0 + 500.0);  // C = C_s + C_t + C_c
  // 125 MB/s is exactly 1 Gbit/s: capacity must exceed the load, so the card is bought.
  cost = select::rig_cost({1000.0, 125e6, 2.0, 2}, transfer, cpus);
  CHECK(cost.transfer_id == "card");
  CHECK(cost.cpu_id == "mid");  // 2.0 cores do not exceed the 2-core CPU either
  CHECK(cost.total == 1000.0 + 80.0 + 500.0);
  // Nothing carries 10 cores.
  CHECK_FALSE(select::rig_cost({0.0, 0.0, 10.0, 1}, transfer, cpus).feasible);
  CHECK(select::cheapest_exceeding(cpus, 8.0) == nullptr);
}

namespace {

// A transfer component of `kind` (set field by field: GCC 12 warns on `where` left to {} in a
// brace list of them).
model::PricedCapacity component(const char* id, double capacity, double price, const char* kind) {
  model::PricedCapacity item;
  item.id = id;
  item.capacity = capacity;
  item.price = price;
  item.kind = kind;
  return item;
}

}  // namespace

TEST_CASE("cost model: eq. 4 buys one component of each transfer kind and sums them") {
  // Cables and switches (issue 39): 0.5 Gbit/s takes the 1 Gbit/s cable (10) and switch (100);
  // 2 Gbit/s the 10 Gbit/s ones (50 + 300); 20 Gbit/s no cable carries.
  std::vector<model::PricedCapacity> transfer = {component("cat5e", 1.0e9, 10, "cable"),
                                                 component("cat6a", 10.0e9, 50, "cable"),
                                                 component("gige_switch", 1.0e9, 100, "switch"),
                                                 component("10g_switch", 10.0e9, 300, "switch")};
  const std::vector<model::PricedCapacity> cpus = {{"cpu", 8.0, 200, {}, {}}};
  select::CostBreakdown cost = select::rig_cost({1000.0, 62.5e6, 1.0, 2}, transfer, cpus);
  CHECK(cost.feasible);
  CHECK(cost.transfer == 10.0 + 100.0);
  CHECK(cost.transfer_id == "cat5e + gige_switch");
  CHECK(cost.total == 1000.0 + 110.0 + 200.0);
  CHECK(select::total_cost({1000.0, 62.5e6, 1.0, 2}, transfer, cpus) == 1310.0);
  cost = select::rig_cost({1000.0, 250e6, 1.0, 2}, transfer, cpus);
  CHECK(cost.transfer == 50.0 + 300.0);
  CHECK(cost.transfer_id == "cat6a + 10g_switch");
  CHECK_FALSE(select::rig_cost({0.0, 2.5e9, 1.0, 1}, transfer, cpus).feasible);
  CHECK(std::isinf(select::total_cost({0.0, 2.5e9, 1.0, 1}, transfer, cpus)));
  // A flat list is one kind: the cheapest item above the load alone, as before.
  for (model::PricedCapacity& item : transfer) item.kind.clear();
  CHECK(select::rig_cost({1000.0, 62.5e6, 1.0, 2}, transfer, cpus).transfer == 10.0);
}

TEST_CASE("cost model: eq. 4's per-sensor kinds buy one component for each sensor's own load") {
  // A cable per sensor (issue 54 item 3), one switch for the rig. By hand: a 0.3 Gbit/s sensor
  // takes the 1 Gbit/s cable (10), a 2 Gbit/s one the 10 Gbit/s cable (50); together they send
  // 2.3 Gbit/s, which needs the 10 Gbit/s switch (300): C_t = 10 + 50 + 300 = 360.
  std::vector<model::PricedCapacity> transfer = {component("cat5e", 1.0e9, 10, "cable"),
                                                 component("cat6a", 10.0e9, 50, "cable"),
                                                 component("gige_switch", 1.0e9, 100, "switch"),
                                                 component("10g_switch", 10.0e9, 300, "switch")};
  transfer[0].per_sensor = transfer[1].per_sensor = true;
  const std::vector<model::PricedCapacity> cpus = {{"cpu", 8.0, 200, {}, {}}};
  CHECK(select::per_sensor_transfer_price(transfer, 0.3e9 / 8) == 10.0);
  CHECK(select::per_sensor_transfer_price(transfer, 2.0e9 / 8) == 50.0);
  CHECK(std::isinf(select::per_sensor_transfer_price(transfer, 20e9 / 8)));  // no cable
  select::RigLoad load{1000.0, 2.3e9 / 8, 1.0, 2};
  load.per_sensor_transfer = 10.0 + 50.0;
  const select::CostBreakdown cost = select::rig_cost(load, transfer, cpus);
  CHECK(cost.feasible);
  CHECK(cost.transfer == 360.0);
  CHECK(cost.transfer_id == "10g_switch + per sensor: cable");
  CHECK(cost.total == 1000.0 + 360.0 + 200.0);
  CHECK(select::total_cost(load, transfer, cpus) == 1560.0);
  // With a shared cable the rig bought one 10 Gbit/s cable (50) for the 2.3 Gbit/s instead.
  transfer[0].per_sensor = transfer[1].per_sensor = false;
  CHECK(select::total_cost({1000.0, 2.3e9 / 8, 1.0, 2}, transfer, cpus) == 1000.0 + 350.0 + 200.0);
  // Only per-sensor kinds: nothing shared to buy, the sensors' own components are C_t.
  const std::vector<model::PricedCapacity> cables_only = {transfer[0], transfer[1]};
  std::vector<model::PricedCapacity> own = cables_only;
  own[0].per_sensor = own[1].per_sensor = true;
  CHECK(select::rig_cost(load, own, cpus).feasible);
  CHECK(select::total_cost(load, own, cpus) == 1000.0 + 60.0 + 200.0);
  load.per_sensor_transfer = std::numeric_limits<double>::infinity();  // a sensor no cable carries
  CHECK_FALSE(select::rig_cost(load, own, cpus).feasible);
}

namespace {

// A random small catalog: 2-4 slots of 1-3 options, 6 angles on a 12 x 4 grid, random
// coverage bits, one or two sectors with random thresholds, random hardware.
select::SearchProblem random_problem(std::mt19937& rng) {
  std::uniform_int_distribution<int> slots(2, 4), options(1, 3), coin(0, 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  select::SearchProblem problem;
  const geometry::RasterGrid grid{12, 4};
  const int angles = 6;
  problem.grids.assign(angles, grid);
  const int slot_count = slots(rng);
  for (int k = 0; k < slot_count; ++k) {
    problem.slots.emplace_back();
    const int option_count = options(rng);
    for (int o = 0; o < option_count; ++o) {
      select::SearchOption option;
      option.price = std::round(50 + 950 * unit(rng));
      option.bandwidth = 1e8 * unit(rng);
      option.cpu = 2.0 * unit(rng);
      const double density = 0.2 + 0.5 * unit(rng);
      std::vector<geometry::SectionRaster> sections;
      for (int a = 0; a < angles; ++a) {
        geometry::SectionRaster raster(grid);
        for (int c = 0; c < grid.columns; ++c) {
          int run_start = -1;
          for (int r = 0; r <= grid.rows; ++r) {
            const bool on = r < grid.rows && unit(rng) < density;
            if (on && run_start < 0) run_start = r;
            if (!on && run_start >= 0) {
              raster.set_column_run(c, run_start, r);
              run_start = -1;
            }
          }
          if (unit(rng) < density) raster.set_floor(c);
        }
        sections.push_back(raster);
      }
      option.sections = std::make_shared<const std::vector<geometry::SectionRaster>>(sections);
      problem.slots.back().push_back(option);
    }
  }
  const int sectors = 1 + coin(rng);
  for (int s = 0; s < sectors; ++s) {
    select::SearchSector sector;
    for (int a = 0; a < angles; ++a) {
      if (unit(rng) < 0.5) sector.angles.push_back(a);
    }
    sector.min_complete = 0.2 + 0.6 * unit(rng);
    sector.min_floor = 0.6 * unit(rng);
    problem.sectors.push_back(sector);
  }
  problem.transfer = {{"slow", 4e8 + 4e8 * unit(rng), 0, {}, {}},
                      {"fast", 4e9, 100 * unit(rng), {}, {}}};
  problem.cpus = {{"a", 1.0 + 2 * unit(rng), 200, {}, {}},
                  {"b", 6.0, 400 + 400 * unit(rng), {}, {}}};
  return problem;
}

// A hand-made problem of one angle on a 4 x 2 grid (8 cells, 4 floor columns), a free link
// and one 100 USD CPU: the tests below fill its slots.
const geometry::RasterGrid kHandGrid{4, 2};

select::SearchProblem one_angle_problem() {
  select::SearchProblem problem;
  problem.grids = {kHandGrid};
  problem.transfer = {{"onboard", 1e9, 0, {}, {}}};
  problem.cpus = {{"cpu", 4.0, 100, {}, {}}};
  return problem;
}

// An option covering cells [first_cell, end_cell) (column-major) and, if asked, every floor
// column.
select::SearchOption hand_option(double price, int first_cell, int end_cell, bool floor,
                                 double cpu = 0.0) {
  select::SearchOption o;
  o.price = price;
  o.cpu = cpu;
  geometry::SectionRaster raster(kHandGrid);
  for (int cell = first_cell; cell < end_cell; ++cell)
    raster.set_column_run(cell / kHandGrid.rows, cell % kHandGrid.rows, cell % kHandGrid.rows + 1);
  if (floor)
    for (int c = 0; c < kHandGrid.columns; ++c) raster.set_floor(c);
  o.sections = std::make_shared<const std::vector<geometry::SectionRaster>>(1, raster);
  return o;
}

// Checks the branch and bound against the brute force on `problem`; whether it has a solution.
bool agrees_with_brute_force(const select::SearchProblem& problem) {
  const select::SearchResult exhaustive = select::brute_force(problem);
  const select::SearchResult bounded = select::branch_and_bound(problem);
  REQUIRE(bounded.found == exhaustive.found);
  if (!exhaustive.found) return false;
  CHECK(bounded.cost.total == exhaustive.cost.total);
  // Among equal costs both keep the largest smallest margin.
  CHECK(bounded.margin == exhaustive.margin);
  CHECK(bounded.margins == exhaustive.margins);
  CHECK(bounded.nodes <= exhaustive.nodes * 3);
  return true;
}

}  // namespace

TEST_CASE("branch and bound finds the brute-force optimum on 200 random small catalogs") {
  std::mt19937 rng(20261121);  // seeded: the same catalogs every run
  int feasible = 0;
  for (int trial = 0; trial < 200; ++trial) {
    INFO("trial " << trial);
    feasible += agrees_with_brute_force(random_problem(rng)) ? 1 : 0;
  }
  CHECK(feasible >= 50);  // enough of them have a solution to compare costs
}

TEST_CASE("branch and bound finds the brute-force optimum with transfer kinds (eq. 4)") {
  std::mt19937 rng(20261128);  // seeded: the same catalogs every run
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int feasible = 0;
  for (int trial = 0; trial < 120; ++trial) {
    INFO("trial " << trial);
    select::SearchProblem problem = random_problem(rng);
    problem.transfer = {component("cable_slow", 3e8 + 6e8 * unit(rng), 0, "cable"),
                        component("cable_fast", 4e9, 30 * unit(rng), "cable"),
                        component("switch_slow", 3e8 + 6e8 * unit(rng), 20, "switch"),
                        component("switch_fast", 4e9, 20 + 150 * unit(rng), "switch")};
    feasible += agrees_with_brute_force(problem) ? 1 : 0;
  }
  CHECK(feasible >= 30);
}

TEST_CASE("branch and bound finds the brute-force optimum with per-sensor transfer (eq. 4)") {
  std::mt19937 rng(20261207);  // seeded before the first run: the same catalogs every run
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int feasible = 0;
  for (int trial = 0; trial < 120; ++trial) {
    INFO("trial " << trial);
    select::SearchProblem problem = random_problem(rng);
    problem.transfer = {component("port_slow", 2e8 + 6e8 * unit(rng), 5 * unit(rng), "port"),
                        component("port_fast", 6e8 + 6e8 * unit(rng), 40 * unit(rng), "port"),
                        component("switch", 4e9, 20 + 100 * unit(rng), "switch")};
    problem.transfer[0].per_sensor = problem.transfer[1].per_sensor = true;
    // Some options send more than either port carries: they can never be bought.
    for (std::vector<select::SearchOption>& slot : problem.slots)
      for (select::SearchOption& option : slot)
        option.transfer_price =
            select::per_sensor_transfer_price(problem.transfer, option.bandwidth);
    feasible += agrees_with_brute_force(problem) ? 1 : 0;
  }
  CHECK(feasible >= 30);
}

TEST_CASE("an excluded assignment is skipped and the next cheapest returned") {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const select::SearchProblem problem = random_problem(rng);
    const select::SearchResult first = select::branch_and_bound(problem);
    if (!first.found) continue;
    const select::SearchResult second = select::branch_and_bound(problem, {first.choice});
    if (second.found) {
      CHECK(second.choice != first.choice);
      CHECK(second.cost.total >= first.cost.total);
    }
  }
}

TEST_CASE("of two rigs of equal cost the one with the larger margin wins") {
  // One slot, two options at the same price (a camera at two pitches): at the one sector
  // angle the first covers cells 2..7 of 8 (75 %), the second cells 0..6 (87.5 %); neither
  // holds the other, so neither dominates. Threshold 50 %: both are feasible and cost the
  // same; margins 25 and 37.5 points: the second wins, and the search reports the tie.
  select::SearchProblem problem = one_angle_problem();
  problem.slots = {{hand_option(200, 2, 8, true), hand_option(200, 0, 7, true)}};
  problem.sectors = {{{0}, 0.5, 0.0}};
  const select::SearchResult bounded = select::branch_and_bound(problem);
  REQUIRE(bounded.found);
  CHECK(bounded.choice == std::vector<int>{1});
  CHECK(bounded.margin == Approx(0.375));
  CHECK(bounded.ties == 2);
  CHECK(bounded.dominated == 0);
  const select::SearchResult exhaustive = select::brute_force(problem);
  CHECK(exhaustive.choice == std::vector<int>{1});
}

TEST_CASE("an option its slot's other option dominates is never tried") {
  // Same price; the second covers cells 0..6, a superset of the first's 0..5: the first can
  // never be the better choice, so it is left out, and the answer is unchanged.
  select::SearchProblem problem = one_angle_problem();
  problem.slots = {{hand_option(200, 0, 6, false, 0.5), hand_option(200, 0, 7, false, 0.5)}};
  problem.sectors = {{{0}, 0.5, 0.0}};
  select::SearchResult bounded = select::branch_and_bound(problem);
  CHECK(bounded.dominated == 1);
  CHECK(bounded.choice == std::vector<int>{1});
  // A superset that loads the CPU more does not dominate: both are tried.
  problem.slots = {{hand_option(200, 0, 6, false, 0.5), hand_option(200, 0, 7, false, 0.6)}};
  bounded = select::branch_and_bound(problem);
  CHECK(bounded.dominated == 0);
  CHECK(bounded.ties == 2);
}

TEST_CASE("with robustness, branch and bound still finds the brute-force optimum") {
  // The same random catalogs, now required to keep half of each sector's thresholds after any
  // one sensor fails, and (every other trial) after every option that does not survive a
  // condition drops out (about half of them).
  std::mt19937 rng(20261125);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int feasible = 0;
  for (int trial = 0; trial < 200; ++trial) {
    INFO("trial " << trial);
    select::SearchProblem problem = random_problem(rng);
    problem.robustness.single_failure = true;
    problem.robustness.condition = trial % 2 == 1;
    for (select::SearchSector sector : problem.sectors) {
      sector.min_complete *= 0.5;
      sector.min_floor *= 0.5;
      problem.robustness.sectors.push_back(sector);
    }
    for (auto& slot : problem.slots) {
      for (select::SearchOption& option : slot) option.survives_condition = unit(rng) < 0.5;
    }
    const select::SearchResult exhaustive = select::brute_force(problem);
    const select::SearchResult bounded = select::branch_and_bound(problem);
    REQUIRE(bounded.found == exhaustive.found);
    if (!exhaustive.found) continue;
    ++feasible;
    CHECK(bounded.cost.total == exhaustive.cost.total);
    CHECK(bounded.margin == exhaustive.margin);
    CHECK(bounded.margins == exhaustive.margins);
  }
  CHECK(feasible >= 20);
}

TEST_CASE("a robust rig needs a second sensor where one suffices otherwise") {
  // One sector angle, threshold 50 %; slot 0 offers a 100 USD sensor covering 6 of 8 cells,
  // slot 1 a 150 USD one covering 5 of 8. Alone the cheap one suffices (100 USD + CPU 100);
  // surviving any single failure at the same threshold needs both: each alone still
  // meets 50 % (75 % and 62.5 %), so the robust optimum is 250 USD + CPU 100.
  select::SearchProblem problem = one_angle_problem();
  problem.slots = {{hand_option(100, 0, 6, true)}, {hand_option(150, 0, 5, true)}};
  problem.sectors = {{{0}, 0.5, 0.0}};
  CHECK(select::branch_and_bound(problem).cost.total == 200);
  problem.robustness.single_failure = true;
  problem.robustness.sectors = problem.sectors;
  const select::SearchResult robust = select::branch_and_bound(problem);
  REQUIRE(robust.found);
  CHECK(robust.cost.total == 350);
  CHECK(robust.choice == std::vector<int>{0, 0});
}

TEST_CASE(
    "the robustness bounds keep the brute-force optimum: n-1 alone, a condition alone, both") {
  // Issue 32's bounds (every undecided slot's failure survivable from the rest; two covers
  // under n-1, one surviving under a condition, each with its least price, bandwidth and CPU
  // load) and the cut of equal-cost subtrees that cannot widen the margins are exact only
  // if no optimum is lost. After-failure thresholds are drawn on their own: below, equal to
  // or above the sector's, zero for one part, so neither rule can lean on the other.
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int feasible = 0;
  int ties_broken = 0;
  for (int trial = 0; trial < 300; ++trial) {
    INFO("trial " << trial);
    select::SearchProblem problem = random_problem(rng);
    problem.robustness.single_failure = trial % 3 != 1;
    problem.robustness.condition = trial % 3 != 0;
    for (select::SearchSector sector : problem.sectors) {
      sector.min_complete *= 1.2 * unit(rng);
      sector.min_floor = unit(rng) < 0.3 ? 0.0 : sector.min_floor * 1.2 * unit(rng);
      problem.robustness.sectors.push_back(sector);
    }
    for (auto& slot : problem.slots) {
      for (select::SearchOption& option : slot) option.survives_condition = unit(rng) < 0.6;
    }
    // Equal prices make ties, so the margin cut is exercised.
    if (trial % 2 == 0) {
      for (auto& slot : problem.slots)
        for (select::SearchOption& option : slot)
          option.price = 300 * std::max(1.0, std::round(option.price / 300));
    }
    const select::SearchResult exhaustive = select::brute_force(problem);
    const select::SearchResult bounded = select::branch_and_bound(problem);
    REQUIRE(bounded.found == exhaustive.found);
    if (!exhaustive.found) continue;
    ++feasible;
    if (exhaustive.ties > 1) ++ties_broken;
    CHECK(bounded.cost.total == exhaustive.cost.total);
    CHECK(bounded.margins == exhaustive.margins);
  }
  CHECK(feasible >= 30);
  CHECK(ties_broken >= 5);
}

namespace {

// An axis-aligned box housing of `size` centred at `centre` [m].
std::shared_ptr<const geometry::ConvexSolid> box_at(const model::Vec3& centre,
                                                    const model::Vec3& size) {
  model::HousingSolid housing;
  housing.size = size;
  model::Pose3 at = model::Pose3::Identity();
  at.translation() = centre;
  return std::make_shared<const geometry::ConvexSolid>(geometry::housing_solid(housing, at));
}

// Independent of the separating axes: two axis-aligned boxes overlap deeper than 1 mm when
// their intervals do on every axis.
bool boxes_overlap(const geometry::ConvexSolid& a, const geometry::ConvexSolid& b) {
  for (int axis = 0; axis < 3; ++axis) {
    double a_low = 1e9, a_high = -1e9, b_low = 1e9, b_high = -1e9;
    for (const model::Vec3& p : a.corners) {
      a_low = std::min(a_low, p[axis]);
      a_high = std::max(a_high, p[axis]);
    }
    for (const model::Vec3& p : b.corners) {
      b_low = std::min(b_low, p[axis]);
      b_high = std::max(b_high, p[axis]);
    }
    if (std::min(a_high, b_high) - std::max(a_low, b_low) <= 0.001) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("two options whose housings overlap are never chosen together: the next rig wins") {
  // Slots A and B each cover half the only angle's cells and floor; slot C covers it all
  // alone for more. A and B together (100 + 100) beat C (300), but their housings, 50 mm
  // boxes 30 mm apart, overlap by 20 mm: the search must return C, as the brute force does.
  select::SearchProblem problem = one_angle_problem();
  select::SearchOption a = hand_option(100, 0, 4, true);
  select::SearchOption b = hand_option(100, 4, 8, true);
  const select::SearchOption c = hand_option(300, 0, 8, true);
  a.housing = box_at({0.0, 0.0, 0.5}, {0.05, 0.05, 0.05});
  b.housing = box_at({0.03, 0.0, 0.5}, {0.05, 0.05, 0.05});
  problem.slots = {{a}, {b}, {c}};
  problem.sectors = {{{0}, 1.0, 1.0}};
  const select::SearchResult bounded = select::branch_and_bound(problem);
  REQUIRE(bounded.found);
  CHECK(bounded.choice == std::vector<int>{-1, -1, 0});
  CHECK(bounded.cost.total == 300.0 + 100.0);  // C and the CPU
  CHECK(bounded.housing_clashes == 1);
  CHECK(select::brute_force(problem).choice == bounded.choice);
  // 60 mm apart the boxes only miss each other: A and B are the rig.
  problem.slots[1][0].housing = box_at({0.06, 0.0, 0.5}, {0.05, 0.05, 0.05});
  CHECK(select::branch_and_bound(problem).choice == std::vector<int>{0, 0, -1});
}

TEST_CASE("with housings, branch and bound finds the brute-force optimum on random catalogs") {
  std::mt19937 rng(20261207);  // seeded: the same catalogs every run
  std::uniform_real_distribution<double> place(-0.06, 0.06);
  int feasible = 0;
  int changed = 0;  // catalogs whose optimum without housings had two that overlap
  for (int trial = 0; trial < 150; ++trial) {
    INFO("trial " << trial);
    select::SearchProblem problem = random_problem(rng);
    const select::SearchResult free = select::brute_force(problem);
    for (auto& slot : problem.slots)
      for (select::SearchOption& option : slot)
        option.housing = box_at({place(rng), place(rng), 0.5}, {0.05, 0.05, 0.05});
    if (!agrees_with_brute_force(problem)) continue;
    ++feasible;
    const select::SearchResult bounded = select::branch_and_bound(problem);
    for (std::size_t j = 0; j < bounded.choice.size(); ++j)
      for (std::size_t k = j + 1; k < bounded.choice.size(); ++k)
        if (bounded.choice[j] >= 0 && bounded.choice[k] >= 0)
          CHECK_FALSE(boxes_overlap(*problem.slots[j][bounded.choice[j]].housing,
                                    *problem.slots[k][bounded.choice[k]].housing));
    if (free.found && bounded.cost.total > free.cost.total + 1e-6) ++changed;
  }
  CHECK(feasible >= 30);
  CHECK(changed >= 5);  // the housings decided some of them
}
