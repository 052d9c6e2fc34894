// Coverage speed on the UR Cleaner (5 sensors, cylinder body) and the TurtleBot 4 (2 sensors,
// its collision meshes as the body), 360 angles, SC complete + floor: the exact path (CGAL
// polygons), the raster path (column intervals into bitsets), and what one candidate rig
// costs the selection search once each sensor's rasters are cached (OR + popcount). Run
// through scripts/bench.sh; Google Benchmark prints medians.
#include <benchmark/benchmark.h>

#include <numbers>
#include <thread>

#include "rigdesign/geometry/section_polygons.hpp"
#include "rigdesign/geometry/section_raster.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/coverage.hpp"

namespace {

using namespace rigdesign;

constexpr int kAngles = 360;
constexpr double kCell = metrics::CoverageSettings{}.raster_cell;  // [m] the default raster cell

struct UrCleaner {
  model::SensorLibrary library = io::load_sensor_library(RIGDESIGN_SOURCE_DIR "/sensors.yaml");
  model::Rig rig;
  geometry::BodyOccluder body{rig.body};
  std::vector<geometry::MountedFov> fovs;
  explicit UrCleaner(const std::string& file)
      : rig(io::load_rig(RIGDESIGN_SOURCE_DIR "/rigs/" + file)), body(rig.body) {
    for (const model::Mount& mount : rig.mounts) {
      fovs.emplace_back(*library.find(mount.sensor_id)->find_mode(mount.mode_id),
                        mount.T_robot_sensor, body, mount.housing_link);
    }
  }
  geometry::SectionFrame frame(int step) const {
    return geometry::section_frame(body, 2 * std::numbers::pi * step / kAngles,
                                   rig.distance_of_interest);
  }
};

const UrCleaner& ur_cleaner() {
  static const UrCleaner instance("ur_cleaner.yaml");
  return instance;
}

const UrCleaner& turtlebot4() {
  static const UrCleaner instance("turtlebot4.yaml");
  return instance;
}

geometry::RasterGrid grid_for(const geometry::SectionFrame& frame) {
  return {static_cast<int>(std::ceil(frame.width() / kCell)),
          static_cast<int>(std::ceil(frame.h / kCell))};
}

void exact_sweep(benchmark::State& state, const UrCleaner& rig) {
  for (auto _ : state) {
    double total = 0.0;
    for (int step = 0; step < kAngles; ++step) {
      const geometry::SectionFrame frame = rig.frame(step);
      std::vector<std::vector<geometry::Polygon2>> polygons;
      geometry::IntervalSet floor;
      for (const geometry::MountedFov& fov : rig.fovs) {
        polygons.push_back(geometry::section_polygons(fov, frame));
        floor = floor.united(geometry::floor_coverage(fov, frame));
      }
      total += geometry::union_area(polygons) / frame.area() + floor.length() / frame.width();
    }
    benchmark::DoNotOptimize(total);
  }
}

double raster_sweep(const UrCleaner& rig, int first_step, int step_stride) {
  double total = 0.0;
  for (int step = first_step; step < kAngles; step += step_stride) {
    const geometry::SectionFrame frame = rig.frame(step);
    geometry::SectionRaster united(grid_for(frame));
    for (const geometry::MountedFov& fov : rig.fovs)
      united |= geometry::rasterize(fov, frame, grid_for(frame));
    total += united.complete_share() + united.floor_share();
  }
  return total;
}

void BM_ExactSweep(benchmark::State& state) {
  exact_sweep(state, ur_cleaner());
}
void BM_RasterSweep(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(raster_sweep(ur_cleaner(), 0, 1));
}
// The TurtleBot 4's body: its collision meshes (the shell alone has 43,970 triangles).
void BM_TurtleBot4ExactSweep(benchmark::State& state) {
  exact_sweep(state, turtlebot4());
}
void BM_TurtleBot4RasterSweep(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(raster_sweep(turtlebot4(), 0, 1));
}

// The same sweep with the angles shared between two threads (this machine has two cores).
void BM_RasterSweepTwoThreads(benchmark::State& state) {
  const UrCleaner& rig = ur_cleaner();
  for (auto _ : state) {
    double odd = 0.0;
    std::thread worker([&] { odd = raster_sweep(rig, 1, 2); });
    const double even = raster_sweep(rig, 0, 2);
    worker.join();
    benchmark::DoNotOptimize(even + odd);
  }
}

void BM_PerCandidateCachedRasters(benchmark::State& state) {
  const UrCleaner& rig = ur_cleaner();
  std::vector<std::vector<geometry::SectionRaster>> cached(rig.fovs.size());
  for (std::size_t i = 0; i < rig.fovs.size(); ++i) {
    for (int step = 0; step < kAngles; ++step) {
      cached[i].push_back(
          geometry::rasterize(rig.fovs[i], rig.frame(step), grid_for(rig.frame(step))));
    }
  }
  for (auto _ : state) {
    double total = 0.0;
    for (int step = 0; step < kAngles; ++step) {
      geometry::SectionRaster united = cached[0][step];
      for (std::size_t i = 1; i < cached.size(); ++i) united |= cached[i][step];
      total += united.complete_share() + united.floor_share();
    }
    benchmark::DoNotOptimize(total);
  }
}

void BM_ComputeCoverageAll(benchmark::State& state) {
  const UrCleaner& rig = ur_cleaner();
  for (auto _ : state) {
    benchmark::DoNotOptimize(metrics::compute_coverage(rig.rig, rig.library, {}));
  }
}

BENCHMARK(BM_ExactSweep)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly();
BENCHMARK(BM_RasterSweep)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly();
BENCHMARK(BM_TurtleBot4ExactSweep)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(BM_TurtleBot4RasterSweep)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(BM_RasterSweepTwoThreads)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(BM_PerCandidateCachedRasters)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();
BENCHMARK(BM_ComputeCoverageAll)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly();

}  // namespace

BENCHMARK_MAIN();
