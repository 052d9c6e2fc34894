// Selection on the bundled UR Cleaner catalog (8 slots, 31 slot options) with its initial
// requirements: branch and bound to proven optimality, and brute force over every
// assignment of the same problem for the ratio. Counters report nodes, rigs evaluated and
// the time per evaluated rig. Run through scripts/bench.sh select.
#include <benchmark/benchmark.h>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/select/selection.hpp"

namespace {

using namespace rigdesign;

struct Bundled {
  model::Catalog catalog = io::load_catalog(RIGDESIGN_SOURCE_DIR "/rigs/catalogs/ur_cleaner.yaml");
  model::SensorLibrary library = io::load_sensor_library(RIGDESIGN_SOURCE_DIR "/sensors.yaml");
  model::Requirements requirements =
      io::load_requirements(RIGDESIGN_SOURCE_DIR "/rigs/requirements/ur_cleaner.yaml");
  select::SelectionSpace space{catalog, library};
  std::vector<std::vector<const select::CatalogOption*>> kept;
  select::SearchProblem problem =
      space.problem_for(select::satisficing_targets(requirements), kept);
};

const Bundled& bundled() {
  static const Bundled instance;
  return instance;
}

void report(benchmark::State& state, const select::SearchResult& result) {
  state.counters["cost_usd"] = result.cost.total;
  state.counters["nodes"] = static_cast<double>(result.nodes);
  state.counters["rigs_evaluated"] = static_cast<double>(result.evaluations);
  state.counters["per_rig"] = benchmark::Counter(
      static_cast<double>(result.evaluations),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_RasteriseCatalog(benchmark::State& state) {
  const Bundled& b = bundled();
  for (auto _ : state) benchmark::DoNotOptimize(select::SelectionSpace(b.catalog, b.library));
}

void BM_BranchAndBound(benchmark::State& state) {
  select::SearchResult result;
  for (auto _ : state) result = select::branch_and_bound(bundled().problem);
  report(state, result);
}

void BM_BruteForce(benchmark::State& state) {
  select::SearchResult result;
  for (auto _ : state) result = select::brute_force(bundled().problem);
  report(state, result);
}

void BM_SelectWithExactVerification(benchmark::State& state) {
  const Bundled& b = bundled();
  for (auto _ : state) benchmark::DoNotOptimize(select::select_cheapest(b.space, b.requirements));
}

BENCHMARK(BM_RasteriseCatalog)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_BranchAndBound)->Unit(benchmark::kMillisecond)->Repetitions(3)->ReportAggregatesOnly();
BENCHMARK(BM_SelectWithExactVerification)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_BruteForce)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
