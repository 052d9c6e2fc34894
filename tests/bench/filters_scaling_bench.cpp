// How the filter stages grow with the cloud: office1.pcd tiled 1, 2, 4, 8 and 16 times side by
// side on the floor (0.25 M to 4 M points), each copy jittered by up to 1 mm (seeded) so no two
// tiles are alike, every stage timed on every size. Linear growth means the same time per
// input point at every size: the table gives ns per point and its ratio to the 1x cloud.
// Then the thread count's effect: SOR and P2 on one and two threads, on an idle machine and
// with a busy-looping thread competing for a core (a robot computer with other work).
// Usage: filters_scaling_bench [stage [tiles [rounds]]]  (a stage name or "all"; for a profile,
// e.g. `perf record filters_scaling_bench SOR 16 20`).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "front_camera_cloud.hpp"
#include "rigdesign/filters/pass_through.hpp"
#include "rigdesign/filters/pipeline.hpp"
#include "rigdesign/filters/ransac_plane.hpp"
#include "rigdesign/filters/voxel_grid.hpp"
#include "rigdesign/io/cloud/cloud_io.hpp"

namespace {

using namespace rigdesign;

/// `tiles` copies of `cloud` on a grid of the floor (4 per row), 0.5 m apart beyond its
/// extent, every point jittered by up to 1 mm per axis.
model::PointCloud tiled(const model::PointCloud& cloud, int tiles, unsigned seed) {
  Eigen::Array3f low = cloud.points.front().array(), high = low;
  for (const model::Point3f& p : cloud.points) {
    low = low.min(p.array());
    high = high.max(p.array());
  }
  const Eigen::Array3f pitch = high - low + 0.5f;
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> jitter(-1e-3f, 1e-3f);
  model::PointCloud out;
  out.origin = cloud.origin;
  out.points.reserve(cloud.size() * static_cast<std::size_t>(tiles));
  for (int t = 0; t < tiles; ++t) {
    const model::Point3f shift(static_cast<float>(t % 4) * pitch.x(),
                               static_cast<float>(t / 4) * pitch.y(), 0.0f);
    for (const model::Point3f& p : cloud.points) {
      out.points.push_back(p + shift +
                           model::Point3f(jitter(random), jitter(random), jitter(random)));
    }
  }
  return out;
}

struct Stage {
  std::string name;
  bool on_voxelised;  // runs on the 3 cm voxel grid's output, as in the pipelines
  std::function<std::size_t(const model::PointCloud&)> run;
};

std::vector<Stage> stages() {
  std::vector<Stage> list = {
      {"voxel_grid", false, [](const auto& c) { return filters::voxel_grid(c).size(); }},
      {"SOR", true, [](const auto& c) { return filters::statistical_outlier_removal(c).size(); }},
      {"pass_through", false, [](const auto& c) { return filters::pass_through(c).size(); }},
      {"RANSAC", true, [](const auto& c) { return filters::fit_plane_ransac(c).inliers.size(); }},
      {"floor_removal_1", true, [](const auto& c) { return filters::remove_floor_1(c).size(); }},
      {"floor_removal_2", true, [](const auto& c) { return filters::remove_floor_2(c).size(); }},
  };
  for (const std::string name : {"P2", "P3", "P4"}) {
    const model::Pipeline pipeline = *filters::preset_pipeline(name);
    list.push_back({name, false, [pipeline](const auto& c) {
                      return filters::run_pipeline(pipeline, c).size();
                    }});
  }
  return list;
}

double median_seconds(const std::function<std::size_t()>& run, int rounds) {
  std::vector<double> times;
  for (int i = 0; i < rounds; ++i) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

/// A thread spinning on one core for as long as it lives: the competing load.
class BusyCore {
 public:
  BusyCore()
      : spinner_([this] {
          volatile double sink = 1.0;
          while (!stop_.load(std::memory_order_relaxed)) sink = sink * 1.0000001;
        }) {}
  ~BusyCore() {
    stop_ = true;
    spinner_.join();
  }
  BusyCore(const BusyCore&) = delete;
  BusyCore& operator=(const BusyCore&) = delete;

 private:
  std::atomic<bool> stop_{false};
  std::thread spinner_;
};

void thread_table(const model::PointCloud& base, int rounds) {
  std::printf("\nthreads (statistical_outlier's `threads`; the output is the same on any count)\n");
  std::printf("  %-5s %6s %-14s %10s %10s %8s %9s\n", "stage", "tiles", "machine", "1 thread",
              "2 threads", "2 vs 1", "points");
  model::StatisticalOutlierParams one, two;
  two.threads = 2;
  const model::Pipeline p2 = *filters::preset_pipeline("P2");
  const model::Pipeline p2_two = filters::with_threads(p2, 2);
  for (const int tiles : {1, 4, 16}) {
    const model::PointCloud cloud = tiled(base, tiles, 1);
    const model::PointCloud voxelised = filters::voxel_grid(cloud);
    for (const bool loaded : {false, true}) {
      const auto row = [&](const char* stage, const std::function<std::size_t()>& single,
                           const std::function<std::size_t()>& dual, std::size_t points) {
        const std::unique_ptr<BusyCore> load = loaded ? std::make_unique<BusyCore>() : nullptr;
        std::vector<double> t1, t2;
        for (int r = 0; r < rounds; ++r) {  // interleaved
          t1.push_back(median_seconds(single, 1));
          t2.push_back(median_seconds(dual, 1));
        }
        std::sort(t1.begin(), t1.end());
        std::sort(t2.begin(), t2.end());
        const double a = t1[t1.size() / 2], b = t2[t2.size() / 2];
        std::printf("  %-5s %6d %-14s %10.2f %10.2f %8.2f %9zu\n", stage, tiles,
                    loaded ? "1 core busy" : "idle", a * 1e3, b * 1e3, b / a, points);
      };
      row(
          "SOR", [&] { return filters::statistical_outlier_removal(voxelised, one).size(); },
          [&] { return filters::statistical_outlier_removal(voxelised, two).size(); },
          voxelised.size());
      row(
          "P2", [&] { return filters::run_pipeline(p2, cloud).size(); },
          [&] { return filters::run_pipeline(p2_two, cloud).size(); }, cloud.size());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string only_stage = argc > 1 ? argv[1] : "all";
  const int only_tiles = argc > 2 ? std::atoi(argv[2]) : 0;
  const int rounds = argc > 3 ? std::max(1, std::atoi(argv[3])) : 5;
  const std::string path = std::string(RIGDESIGN_SOURCE_DIR) + "/../shared/data/real/office1.pcd";
  if (!std::filesystem::exists(path)) {
    std::printf("%s: not found\n", path.c_str());
    return 1;
  }
  const model::PointCloud base = bench::as_front_camera(io::read_cloud(path));
  std::printf("filter stages on office1.pcd tiled (jittered, seed 1), one thread, median of %d\n",
              rounds);
  std::printf("  %-16s %6s %10s %10s %10s %8s\n", "stage", "tiles", "points in", "ms", "ns/point",
              "vs 1x");
  for (const Stage& stage : stages()) {
    if (only_stage != "all" && only_stage != stage.name) continue;
    double first_per_point = 0;
    for (const int tiles : {1, 2, 4, 8, 16}) {
      if (only_tiles != 0 && tiles != only_tiles) continue;
      const model::PointCloud cloud = tiled(base, tiles, 1);
      const model::PointCloud input = stage.on_voxelised ? filters::voxel_grid(cloud) : cloud;
      const double seconds = median_seconds([&] { return stage.run(input); }, rounds);
      const double per_point = seconds * 1e9 / static_cast<double>(input.size());
      if (first_per_point == 0) first_per_point = per_point;
      std::printf("  %-16s %6d %10zu %10.2f %10.1f %8.2f\n", stage.name.c_str(), tiles,
                  input.size(), seconds * 1e3, per_point, per_point / first_per_point);
    }
  }
  if (only_stage == "all" || only_stage == "threads") thread_table(base, rounds);
  return 0;
}
