// Issue 6, item 6: our voxel layer against OctoMap 1.9 (Debian's liboctomap-dev, its library
// defaults and paper 3's hit 1, 0.1 m) on the same simulated frames of paper 3's cell, same
// process, one thread: paper 3's scores near the person, the whole-cell ghost area and trail,
// and insertion throughput on the same rays.
// Usage: occupancy_vs_octomap_bench [duration_s [rate_hz]].
#include <octomap/octomap.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "rigdesign/costmap/voxel_layer.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/occupancy/occupancy_evaluation.hpp"
#include "rigdesign/occupancy/occupancy_sweep.hpp"
#include "rigdesign/occupancy/octomap_mapper.hpp"
#include "rigdesign/sim/ray_caster.hpp"
#include "rigdesign/sim/scene_library.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

namespace {

using namespace rigdesign;

constexpr double kResolution = 0.1;  // [m] paper 3's OctoMap row in DESIGN.md
constexpr double kMinHeight = 0.1;   // [m] as `rigdesign occupancy`'s default

std::string cell(double value, int decimals) {
  if (std::isnan(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

void print_run(const occupancy::OccupancyRun& run) {
  const occupancy::OccupancyPhase& a = run.all;
  std::printf("| %-26s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", run.mapper.c_str(),
              cell(a.object.precision, 3).c_str(), cell(a.object.recall, 3).c_str(),
              cell(a.object.f1, 3).c_str(), cell(a.object.f2, 3).c_str(),
              cell(a.object.f3, 3).c_str(), cell(a.ghost_area, 2).c_str(),
              cell(run.moving.ghost_area, 2).c_str(), cell(run.stationary.ghost_area, 2).c_str(),
              cell(a.trail_length_max, 2).c_str(), cell(a.update_ms, 1).c_str());
}

struct Frames {
  std::vector<std::vector<model::PointCloud>> clouds;
  std::size_t points = 0;
};

// The cell's frames as the evaluation makes them (world frame, sensor origins set).
Frames simulate(const model::Scene& scene, const std::vector<occupancy::CellSensor>& sensors,
                int count, double rate) {
  Frames frames;
  std::mt19937_64 rng(1);
  for (int k = 0; k < count; ++k) {
    const sim::RayCaster caster(scene.at(k / rate));
    std::vector<model::PointCloud> clouds;
    for (const occupancy::CellSensor& sensor : sensors) {
      clouds.push_back(sim::simulate_frame(caster, sensor.mode, sim::ray_pattern(sensor.mode),
                                           sensor.T_world_sensor, sim::SimulationSettings{}, rng));
      frames.points += clouds.back().size();
    }
    frames.clouds.push_back(std::move(clouds));
  }
  return frames;
}

// Whole passes over the frames, timed in interleaved rounds (ours, OctoMap), medians.
constexpr int kThroughputRounds = 7;

double seconds_of(const std::function<void()>& insert) {
  const auto start = std::chrono::steady_clock::now();
  insert();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void throughput(const model::Scene& scene, const std::vector<occupancy::CellSensor>& sensors) {
  const Frames frames = simulate(scene, sensors, 20, 5.0);
  // The same rays whole: a window holding every ray (8 x 8 m, z 0-3 m, above every sensor),
  // no range limit, every end point marks.
  costmap::GridWindow window = occupancy::centred_window(8.0, kResolution);
  costmap::VoxelLayerParams params;
  params.z_max = 3.0;
  params.z_resolution = kResolution;
  costmap::ObservationSource source;
  source.obstacle_max_range = source.raytrace_max_range = 1e9;
  source.min_obstacle_height = -1e9;
  source.max_obstacle_height = 1e9;
  const auto octomap_run = [&] {
    octomap::OcTree tree(kResolution);
    for (const auto& clouds : frames.clouds) {
      for (const model::PointCloud& cloud : clouds) {
        octomap::Pointcloud scan;
        for (const model::Point3f& p : cloud.points) scan.push_back(p.x(), p.y(), p.z());
        tree.insertPointCloud(
            scan, octomap::point3d(cloud.origin.x(), cloud.origin.y(), cloud.origin.z()), -1.0);
      }
    }
  };
  const auto ours_run = [&] {
    costmap::VoxelLayer layer(window, params);
    for (const auto& clouds : frames.clouds) {
      for (const model::PointCloud& cloud : clouds)
        layer.insert({&cloud, model::Pose3::Identity(), source});
    }
  };
  // Interleaved rounds, medians: a change of load during the run falls on both alike.
  std::vector<double> octomap_times, ours_times;
  for (int round = 0; round < kThroughputRounds; ++round) {
    octomap_times.push_back(seconds_of(octomap_run));
    ours_times.push_back(seconds_of(ours_run));
  }
  const double octomap_s = median_of(octomap_times);
  const double ours_s = median_of(ours_times);
  const double points = static_cast<double>(frames.points);
  std::printf(
      "\nInsertion throughput, %zu frames (%.0f points), 0.1 m, full rays, one thread, median "
      "of %d interleaved rounds:\n",
      frames.clouds.size(), points, kThroughputRounds);
  std::printf("| mapper | s | points/s |\n|---|---|---|\n");
  std::printf("| OctoMap insertPointCloud | %.3f | %.2f M |\n", octomap_s,
              points / octomap_s / 1e6);
  std::printf("| our VoxelLayer::insert | %.3f | %.2f M |\n", ours_s, points / ours_s / 1e6);
  std::printf("ratio ours / OctoMap: %.1fx (target >= 5x)\n", octomap_s / ours_s);
}

}  // namespace

int main(int argc, char** argv) {
  const double duration = argc > 1 ? std::atof(argv[1]) : 96.0;
  const double rate = argc > 2 ? std::atof(argv[2]) : 5.0;
  const model::Rig rig = io::load_rig(RIGDESIGN_SOURCE_DIR "/rigs/cell.yaml");
  const model::SensorLibrary library =
      io::load_sensor_library(RIGDESIGN_SOURCE_DIR "/sensors.yaml");
  std::vector<occupancy::CellSensor> sensors;
  for (const model::Mount& mount : rig.mounts) {
    sensors.push_back(
        {mount.id, *library.find(mount.sensor_id)->find_mode(mount.mode_id), mount.T_robot_sensor});
  }
  const model::Scene scene = sim::make_scene("cell", 1);

  occupancy::VoxelMapperParams base;
  base.source.obstacle_max_range = base.source.raytrace_max_range = 10.0;
  base.source.min_obstacle_height = kMinHeight;
  const std::vector<double> voxels = {0.05, 0.1, 0.15, 0.2};
  const std::vector<occupancy::PersistenceSetting> settings = {{false, 0, 0}};
  std::vector<occupancy::VoxelMapperParams> grid = occupancy::sweep_grid(voxels, settings, base);
  for (const occupancy::PersistenceSetting& hit :
       {occupancy::PersistenceSetting{true, 3, 30}, occupancy::PersistenceSetting{true}}) {
    const std::vector<occupancy::PersistenceSetting> one = {hit};
    const std::vector<double> tenth = {kResolution};
    for (const occupancy::VoxelMapperParams& params : occupancy::sweep_grid(tenth, one, base))
      grid.push_back(params);
  }
  auto ours = occupancy::make_sweep_mappers(grid, model::SourceLocation{"(bench)"});
  // OctoMap with its library defaults (hit 0.7, miss 0.4, clamps 0.1192 / 0.971) and as paper 3
  // ran it (hit 1, octomap_server's clamps 0.12 / 0.97).
  occupancy::OctoMapParams library_defaults;
  library_defaults.hit = 0.7;
  library_defaults.clamp_min = 0.1192;
  library_defaults.clamp_max = 0.971;
  const auto octomap_defaults = occupancy::make_octomap_mapper(library_defaults);
  const auto octomap_paper = occupancy::make_octomap_mapper({});
  std::vector<occupancy::OccupancyMapper*> mappers = {octomap_defaults.get(), octomap_paper.get()};
  for (const auto& mapper : ours) mappers.push_back(mapper.get());
  occupancy::OccupancyEvalParams params;
  params.duration = duration;
  params.rate = rate;
  params.min_height = kMinHeight;
  const std::vector<occupancy::OccupancyRun> runs =
      occupancy::evaluate_occupancy(scene, sensors, mappers, params);

  std::printf(
      "Cell, %zu frames at %.1f Hz (robot moving until %.0f s), same frames for every mapper\n",
      runs.front().frames.size(), rate, params.moving_until);
  std::printf(
      "| mapper | P | R | F1 | F2 | F3 | ghost m2 | ghost mov | ghost still | trail (p90) max m | "
      "ms/update |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const occupancy::OccupancyRun& run : runs) print_run(run);
  throughput(scene, sensors);
  return 0;
}
