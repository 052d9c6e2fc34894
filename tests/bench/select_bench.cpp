// Selection with the UR Cleaner's initial requirements: on the bundled catalog (8 slots, 31
// slot options), branch and bound to proven optimality and brute force over every
// assignment of the same problem for the ratio; on the bundled pose-range catalog (159
// options) and on the same with finer steps (303 options, written here), branch and bound
// alone (brute force would visit 10^13 assignments), for the growth; on the Jackal's own
// description (171 options) the whole select, loading and rasterising included; with any one
// failure to survive (issue 32) on 31, 159 and 303 options. Counters report nodes, rigs
// evaluated and the time per evaluated rig. Run through scripts/bench.sh select.
#include <benchmark/benchmark.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/select/selection.hpp"

namespace {

using namespace rigdesign;

// The pose-range catalog with finer steps on every range: 303 slot options.
std::string finer_catalog() {
  std::ifstream in(RIGDESIGN_SOURCE_DIR "/rigs/catalogs/ur_cleaner_pose_ranges.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::pair<const char*, const char*> finer[] = {
      {"sensor_library: ../../sensors.yaml",
       "sensor_library: " RIGDESIGN_SOURCE_DIR "/sensors.yaml"},
      {"{min: 10, max: 40, step: 5}", "{min: 10, max: 40, step: 2}"},
      {"{min: 0.10, max: 0.30, step: 0.05}", "{min: 0.10, max: 0.30, step: 0.02}"},
      {"{min: 1.04, max: 1.24, step: 0.1}", "{min: 1.04, max: 1.24, step: 0.04}"},
      {"{min: 10, max: 30, step: 10}", "{min: 10, max: 30, step: 5}"}};
  for (const auto& [from, to] : finer) {
    for (std::size_t at = yaml.find(from); at != std::string::npos; at = yaml.find(from, at)) {
      yaml.replace(at, std::strlen(from), to);
      at += std::strlen(to);
    }
  }
  const std::string path =
      (std::filesystem::temp_directory_path() / "rigdesign_bench_303.yaml").string();
  std::ofstream(path) << yaml;
  return path;
}

constexpr const char* kPlainRequirements =
    RIGDESIGN_SOURCE_DIR "/rigs/requirements/ur_cleaner.yaml";
// The same with any one sensor's failure to survive (issue 32).
constexpr const char* kRobustRequirements =
    RIGDESIGN_SOURCE_DIR "/rigs/requirements/ur_cleaner_robust.yaml";

struct Bundled {
  explicit Bundled(const std::string& file = RIGDESIGN_SOURCE_DIR "/rigs/catalogs/ur_cleaner.yaml",
                   const std::string& requirements_file = kPlainRequirements)
      : catalog(io::load_catalog(file)), requirements(io::load_requirements(requirements_file)) {}
  model::Catalog catalog;
  model::SensorLibrary library = io::load_sensor_library(RIGDESIGN_SOURCE_DIR "/sensors.yaml");
  model::Requirements requirements;
  select::SelectionSpace space{catalog, library};
  std::vector<std::vector<const select::CatalogOption*>> kept;
  select::SearchProblem problem =
      space.problem_for(select::satisficing_targets(requirements), kept);
};

const Bundled& bundled() {
  static const Bundled instance;
  return instance;
}

const Bundled& pose_ranges() {
  static const Bundled instance(RIGDESIGN_SOURCE_DIR "/rigs/catalogs/ur_cleaner_pose_ranges.yaml");
  return instance;
}

const Bundled& finer_pose_ranges() {
  static const Bundled instance(finer_catalog());
  return instance;
}

const Bundled& robust(int options) {
  static const Bundled bundled31(RIGDESIGN_SOURCE_DIR "/rigs/catalogs/ur_cleaner.yaml",
                                 kRobustRequirements);
  static const Bundled ranges159(RIGDESIGN_SOURCE_DIR "/rigs/catalogs/ur_cleaner_pose_ranges.yaml",
                                 kRobustRequirements);
  static const Bundled finer303(finer_catalog(), kRobustRequirements);
  return options == 31 ? bundled31 : options == 159 ? ranges159 : finer303;
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

void BM_BranchAndBoundPoseRanges159(benchmark::State& state) {
  select::SearchResult result;
  for (auto _ : state) result = select::branch_and_bound(pose_ranges().problem);
  report(state, result);
}

void BM_BranchAndBoundPoseRanges303(benchmark::State& state) {
  select::SearchResult result;
  for (auto _ : state) result = select::branch_and_bound(finer_pose_ranges().problem);
  report(state, result);
}

void BM_SelectPoseRanges159(benchmark::State& state) {
  const Bundled& b = pose_ranges();
  for (auto _ : state) benchmark::DoNotOptimize(select::select_cheapest(b.space, b.requirements));
}

// Issue 30: the Jackal's description (both laser accessories) as the body, 171 options: load
// the catalog (the description's xacro expansion and meshes), rasterise every option on the
// collision geometry and search to proven optimum with exact verification, as `select` does.
void BM_SelectJackalDescription171(benchmark::State& state) {
  const std::string file = RIGDESIGN_SOURCE_DIR "/rigs/catalogs/jackal_pose_ranges.yaml";
  const model::SensorLibrary library =
      io::load_sensor_library(RIGDESIGN_SOURCE_DIR "/sensors.yaml");
  const model::Requirements requirements =
      io::load_requirements(RIGDESIGN_SOURCE_DIR "/rigs/requirements/jackal.yaml");
  std::size_t options = 0;
  for (auto _ : state) {
    model::Catalog catalog = io::load_catalog(file);
    catalog.body.area_height = requirements.area_height;
    const select::SelectionSpace space(catalog, library);
    options = space.option_count();
    benchmark::DoNotOptimize(select::select_cheapest(space, requirements));
  }
  state.counters["options"] = static_cast<double>(options);
}

// Issue 32: the search with any one failure to survive, and the whole select_cheapest
// (search, exact verification of the rig and each failure, pose refinement, robustness
// cost), on 31, 159 and 303 options. On the fixed-slot 31 no rig survives the front
// camera's failure: select decides that before the search (sector_needing_one_slot).
void BM_BranchAndBoundRobust(benchmark::State& state) {
  const Bundled& b = robust(static_cast<int>(state.range(0)));
  select::SearchResult result;
  for (auto _ : state) result = select::branch_and_bound(b.problem);
  report(state, result);
}

void BM_SelectRobust(benchmark::State& state) {
  const Bundled& b = robust(static_cast<int>(state.range(0)));
  select::Selection selection;
  for (auto _ : state) selection = select::select_cheapest(b.space, b.requirements);
  state.counters["cost_usd"] = selection.found ? selection.cost.total : 0.0;
  state.counters["nodes"] = static_cast<double>(selection.search.nodes);
}

// Issue 55: the Jackal description catalog made finer, for the growth from about 150 to
// more than 1,000 options (counted after the poses the body or a housing rules out): the
// bundled steps (131 options), the 579-option catalog (front pitch 1.25 deg, yaw
// -10/0/10 deg; rear pitch 1.25 deg; sides 5 deg: 375 left), and a finer one (front yaw every
// 2.5 deg, rear yaw every 5 deg, sides 2.5 deg: 1,215 left).
std::string jackal_catalog(int size) {
  std::ifstream in(RIGDESIGN_SOURCE_DIR "/rigs/catalogs/jackal_pose_ranges.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const bool finest = size > 579;
  const std::pair<std::string, std::string> edits[] = {
      {"sensor_library: ../../sensors.yaml",
       "sensor_library: " RIGDESIGN_SOURCE_DIR "/sensors.yaml"},
      {"description: ../robots/", "description: " RIGDESIGN_SOURCE_DIR "/rigs/robots/"},
      {"package_paths: [../robots]", "package_paths: [" RIGDESIGN_SOURCE_DIR "/rigs/robots]"},
      {"rpy_deg: [0, {min: 0, max: 40, step: 2.5}, 0]}",
       std::string("rpy_deg: [0, {min: 0, max: 40, step: 1.25}, {min: -10, max: 10, step: ") +
           (finest ? "2.5" : "10") + "}]}"},
      {"rpy_deg: [0, {min: 0, max: 40, step: 2.5}, 180]}",
       finest ? "rpy_deg: [0, {min: 0, max: 40, step: 1.25}, {min: 170, max: 190, step: 5}]}"
              : "rpy_deg: [0, {min: 0, max: 40, step: 1.25}, 180]}"},
      {"{min: 0, max: 40, step: 10}, 90]",
       finest ? "{min: 0, max: 40, step: 2.5}, 90]" : "{min: 0, max: 40, step: 5}, 90]"},
      {"{min: 0, max: 40, step: 10}, -90]",
       finest ? "{min: 0, max: 40, step: 2.5}, -90]" : "{min: 0, max: 40, step: 5}, -90]"}};
  for (std::size_t i = 0; i < std::size(edits); ++i) {
    if (size <= 171 && i >= 3) break;  // the bundled steps
    const std::size_t at = yaml.find(edits[i].first);
    if (at == std::string::npos) throw std::runtime_error("bench catalog: no " + edits[i].first);
    yaml.replace(at, edits[i].first.size(), edits[i].second);
  }
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("rigdesign_bench_jackal_" + std::to_string(size) + ".yaml"))
                               .string();
  std::ofstream(path) << yaml;
  return path;
}

// The whole search side of `select` on the Jackal's description (no files written): load the
// catalog with its xacro and meshes, place and rasterise every option, search, verify,
// refine, and the search for a cheaper rig beside it. Arg: 171, 579 or 1000 (see above).
void BM_SelectJackalGrowth(benchmark::State& state) {
  const std::string file = jackal_catalog(static_cast<int>(state.range(0)));
  const model::SensorLibrary library =
      io::load_sensor_library(RIGDESIGN_SOURCE_DIR "/sensors.yaml");
  const model::Requirements requirements =
      io::load_requirements(RIGDESIGN_SOURCE_DIR "/rigs/requirements/jackal.yaml");
  std::size_t options = 0;
  select::Selection selection;
  for (auto _ : state) {
    model::Catalog catalog = io::load_catalog(file);
    catalog.body.area_height = requirements.area_height;
    const select::SelectionSpace space(catalog, library);
    options = space.option_count();
    selection = select::select_cheapest(space, requirements);
  }
  state.counters["options"] = static_cast<double>(options);
  state.counters["nodes"] = static_cast<double>(selection.search.nodes);
  state.counters["cost_usd"] = selection.found ? selection.cost.total : 0.0;
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
BENCHMARK(BM_BranchAndBoundPoseRanges159)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_BranchAndBoundPoseRanges303)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_SelectPoseRanges159)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_SelectJackalDescription171)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_SelectJackalGrowth)
    ->Arg(171)
    ->Arg(579)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_BranchAndBoundRobust)
    ->Arg(159)
    ->Arg(303)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_SelectRobust)
    ->Arg(31)
    ->Arg(159)
    ->Arg(303)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
BENCHMARK(BM_BruteForce)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
