// Issue 6, item 5: every mapper on the same simulated frames of the cell, scored per frame
// near the person (paper 3) and over the whole window (ghosts, trail, delays, planner grid).
#include "rigdesign/occupancy/occupancy_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/parallel_for.hpp"
#include "rigdesign/occupancy/approximate_sync.hpp"
#include "rigdesign/occupancy/occupancy_actor_points.hpp"
#include "rigdesign/occupancy/occupancy_hull_region.hpp"
#include "rigdesign/occupancy/occupancy_link_volumes.hpp"
#include "rigdesign/occupancy/occupancy_trail.hpp"
#include "rigdesign/sim/decimation.hpp"
#include "rigdesign/sim/mean_pooling.hpp"
#include "rigdesign/sim/noise_stream.hpp"
#include "rigdesign/sim/ray_caster.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

namespace rigdesign::occupancy {
namespace {

constexpr double kNoScore = std::numeric_limits<double>::quiet_NaN();

// Frames a run may simulate: an hour at 100 Hz, the largest --duration at the largest --rate.
// Judged in floating point before it becomes the loop's count (issue 53 item 3).
constexpr double kMaxFrames = 3600.0 * 100.0;

// The run's frame count, refused below one frame (a run of 1 s at 1e-300 Hz used to score one
// frame anyway, as if asked for) or above kMaxFrames.
int frame_count(const OccupancyEvalParams& params) {
  const double frames = std::floor(params.duration * params.rate + 1e-9);
  if (frames >= 1.0 && frames <= kMaxFrames) return static_cast<int>(frames);
  throw model::InputError(model::Diagnostic{
      {"(command line)", 0, 0},
      "--duration, --rate",
      model::format_number(params.duration) + " s at " + model::format_number(params.rate) +
          " Hz is " + model::format_number(params.duration * params.rate, 3) + " frames",
      "a run of 1 to " + model::format_number(kMaxFrames) + " frames (duration x rate)"});
}

model::TriangleMesh static_scenery(const model::Scene& scene) {
  model::TriangleMesh mesh;
  for (const model::SceneObject& object : scene.objects) mesh.append(object.mesh);
  return mesh;
}

// What every mapper on one lattice is scored against at one frame.
struct LatticeTruth {
  VoxelLattice lattice;
  costmap::GridWindow window;
  std::vector<costmap::VoxelKey> scenery;  // static, computed once
  std::vector<costmap::VoxelKey> object;   // the moving object now
  std::vector<costmap::VoxelKey> seen;     // voxels holding a point this frame
  std::vector<std::uint8_t> columns;       // every truth voxel's column
  std::vector<std::uint8_t> dilated;       // columns dilated by the robot radius
};

bool same_lattice(const VoxelLattice& a, const VoxelLattice& b) {
  return a.resolution == b.resolution && a.z_resolution == b.z_resolution && a.z_min == b.z_min &&
         a.z_max == b.z_max;
}

// Paper 3's neighbourhood: predicted voxels within the margin of the object's box in x and y,
// static scenery left out (the plate is not the person's false positive).
std::vector<costmap::VoxelKey> near_object(const std::vector<costmap::VoxelKey>& predicted,
                                           const LatticeTruth& truth, double margin) {
  if (truth.object.empty()) return {};
  int x0 = truth.object.front().x, x1 = x0, y0 = truth.object.front().y, y1 = y0;
  for (const costmap::VoxelKey& key : truth.object) {
    x0 = std::min(x0, key.x), x1 = std::max(x1, key.x);
    y0 = std::min(y0, key.y), y1 = std::max(y1, key.y);
  }
  const int reach = static_cast<int>(std::ceil(margin / truth.lattice.resolution - 1e-9));
  std::vector<costmap::VoxelKey> near;
  for (const costmap::VoxelKey& key : predicted) {
    if (key.x < x0 - reach || key.x > x1 + reach || key.y < y0 - reach || key.y > y1 + reach)
      continue;
    if (std::binary_search(truth.scenery.begin(), truth.scenery.end(), key)) continue;
    near.push_back(key);
  }
  return near;
}

// Paper 3's candidates: the shown voxels in the truth, and those whose centre lies within half a
// voxel side of the hull of the object's points; static scenery left out.
std::vector<costmap::VoxelKey> in_hull(const std::vector<costmap::VoxelKey>& predicted,
                                       const LatticeTruth& truth, const HullRegion& hull) {
  const VoxelLattice& lattice = truth.lattice;
  const double grow = 0.5 * std::min(lattice.resolution, lattice.z_resolution);
  std::vector<costmap::VoxelKey> inside;
  for (const costmap::VoxelKey& key : predicted) {
    if (std::binary_search(truth.scenery.begin(), truth.scenery.end(), key)) continue;
    const model::Vec3 centre((key.x + 0.5) * lattice.resolution, (key.y + 0.5) * lattice.resolution,
                             lattice.z_min + (key.z + 0.5) * lattice.z_resolution);
    if (std::binary_search(truth.object.begin(), truth.object.end(), key) ||
        hull.contains(centre, grow)) {
      inside.push_back(key);
    }
  }
  return inside;
}

// The scored band: the voxel rows wholly at or above min_height. The peers' front ends mark
// the floor (octomap_server and voxblox_ros insert every point), and a row reaching below
// min_height holds floor returns at any voxel length (at 0.2 m, row 0 spans the floor and the
// person's ankles), so truth and maps are both scored from the first row above it.
std::vector<costmap::VoxelKey> in_scored_band(std::vector<costmap::VoxelKey> keys,
                                              const VoxelLattice& lattice, double min_height) {
  std::erase_if(keys, [&](const costmap::VoxelKey& key) {
    return lattice.z_min + key.z * lattice.z_resolution < min_height - 1e-9;
  });
  return keys;
}

// Per mapper: the running state of its whole-window measures.
struct Tracking {
  TrailTracker trail;
  ChangeDelays delays;
  // The scored voxels the mapper showed after its last update (none before the first): the map
  // one update late, kept rather than asked for again before the next update.
  std::vector<costmap::VoxelKey> shown_before;
};

void finish_phase(OccupancyPhase& phase, const std::vector<const OccupancyFrame*>& frames) {
  phase.frames = frames.size();
  std::vector<Scores> object, late, master;
  double seconds = 0.0, points = 0.0;
  for (const OccupancyFrame* frame : frames) {
    object.push_back(scores_of(frame->object));
    late.push_back(scores_of(frame->object_late));
    if (frame->has_master) master.push_back(scores_of(frame->master));
    phase.ghost_area += frame->ghost_area;
    phase.ghost_area_max = std::max(phase.ghost_area_max, frame->ghost_area);
    phase.trail_area += frame->trail_area;
    phase.trail_length += frame->trail_length;
    phase.trail_length_max = std::max(phase.trail_length_max, frame->trail_length);
    phase.master_ghost_area += frame->master_ghost_area;
    phase.never_seen += frame->misses.never_seen;
    phase.seen_not_kept += frame->misses.seen_not_kept;
    seconds += frame->update_seconds;
    points += static_cast<double>(frame->points);
  }
  const double n = frames.empty() ? kNoScore : static_cast<double>(frames.size());
  phase.object = mean_scores(object);
  phase.object_late = mean_scores(late);
  phase.master = master.empty() ? Scores{kNoScore, kNoScore, kNoScore, kNoScore, kNoScore}
                                : mean_scores(master);
  phase.ghost_area /= n;
  phase.trail_area /= n;
  phase.trail_length /= n;
  phase.master_ghost_area /= n;
  phase.update_ms = seconds / n * 1e3;
  phase.points_per_second = seconds > 0.0 ? points / seconds : kNoScore;
}

// Per sensor: its mode decimated to the camera stride, its rays and its noise stream.
struct OccupancySensing {
  std::vector<std::vector<model::Vec3>> rays;
  std::vector<model::SensorMode> modes;
  std::vector<std::mt19937_64> streams;
  std::vector<int> pooled_columns;  // > 0: the sensor's organised frame is mean-pooled
};

OccupancySensing occupancy_sensing(std::span<const CellSensor> sensors,
                                   const OccupancyEvalParams& params) {
  OccupancySensing sensing;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    sensing.modes.push_back(sim::decimated_mode(sensors[i].mode, params.camera_stride, 1));
    sensing.rays.push_back(sim::ray_pattern(sensing.modes.back()));
    sensing.streams.push_back(sim::noise_stream(params.seed, i));
    const int columns = sim::pixel_grid_columns(sensing.rays.back());
    const bool pooled = params.camera_pooling > 1 && sensing.modes.back().is_camera();
    if (pooled && columns == 0) {
      throw std::invalid_argument("evaluate_occupancy: camera '" + sensors[i].id +
                                  "' has no full pixel grid to mean-pool (a cone FOV)");
    }
    sensing.pooled_columns.push_back(pooled ? columns : 0);
  }
  return sensing;
}

// One truth per distinct lattice; mappers share it. `truth_of` gets each mapper's.
std::vector<LatticeTruth> lattice_truths(const model::Scene& scene,
                                         std::span<OccupancyMapper* const> mappers,
                                         const OccupancyEvalParams& params,
                                         std::vector<std::size_t>& truth_of) {
  const model::TriangleMesh scenery = static_scenery(scene);
  std::vector<LatticeTruth> truths;
  for (OccupancyMapper* mapper : mappers) {
    const VoxelLattice lattice = mapper->lattice();
    auto found = std::find_if(truths.begin(), truths.end(), [&](const LatticeTruth& t) {
      return same_lattice(t.lattice, lattice);
    });
    if (found == truths.end()) {
      LatticeTruth truth;
      truth.lattice = lattice;
      truth.window = centred_window(params.window_size, lattice.resolution);
      truth.scenery = voxelise_surface(scenery, lattice, params.min_height);
      truths.push_back(std::move(truth));
      found = truths.end() - 1;
    }
    truth_of.push_back(static_cast<std::size_t>(found - truths.begin()));
  }
  return truths;
}

// The scene at one sensor stamp: its ray caster and the moving object there.
struct StampedScene {
  double stamp;
  sim::RayCaster caster;
  model::TriangleMesh object;
  Eigen::AlignedBox3d object_box;
};

// What every sensor recorded for one evaluation tick, and the object's truth points in it.
struct SensedFrame {
  std::size_t points = 0;
  model::Pose3 T_world_object;     // at the fused set's latest stamp
  model::TriangleMesh object_now;  // likewise
  std::vector<model::Vec3> on_object;
};

// Each sensor's stamp at `tick`: the approximate-time set, or the tick for all.
std::vector<double> sensor_stamps(std::span<const FrameClock> clocks, std::size_t sensors,
                                  double tick) {
  if (clocks.empty()) return std::vector<double>(sensors, tick);
  return approximate_time_set(clocks, tick);
}

// One scene per distinct stamp; `scene_of[i]` is sensor i's.
std::vector<std::unique_ptr<StampedScene>> stamped_scenes(const model::Scene& scene,
                                                          const std::vector<double>& stamps,
                                                          std::vector<std::size_t>& scene_of) {
  const model::MovingObject& object = scene.moving.front();
  std::vector<std::unique_ptr<StampedScene>> scenes;
  scene_of.clear();
  for (const double stamp : stamps) {
    const auto found = std::find_if(scenes.begin(), scenes.end(),
                                    [&](const auto& s) { return s->stamp == stamp; });
    scene_of.push_back(static_cast<std::size_t>(found - scenes.begin()));
    if (found != scenes.end()) continue;
    model::TriangleMesh object_mesh;
    object_mesh.append(object.mesh, object.T_world_object(stamp));
    Eigen::AlignedBox3d box;
    for (const model::Vec3& v : object_mesh.vertices) box.extend(v);
    scenes.push_back(std::make_unique<StampedScene>(
        StampedScene{stamp, sim::RayCaster(scene.at(stamp)), std::move(object_mesh), box}));
  }
  return scenes;
}

// Every sensor's frame in its own stamp's scene, in sensor order (each draws from its own
// stream); returns the number of points.
std::size_t simulate_cell_clouds(const std::vector<std::unique_ptr<StampedScene>>& scenes,
                                 const std::vector<std::size_t>& scene_of,
                                 std::span<const CellSensor> sensors, OccupancySensing& sensing,
                                 const OccupancyEvalParams& params,
                                 std::vector<model::PointCloud>& clouds) {
  const sim::SimulationSettings settings{0.0, true, false, false};
  const sim::SimulationSettings organised{0.0, true, false, true};
  std::size_t points = 0;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const sim::RayCaster& caster = scenes[scene_of[i]]->caster;
    if (sensing.pooled_columns[i] > 0) {
      clouds[i] = sim::mean_pool(
          sim::simulate_frame(caster, sensing.modes[i], sensing.rays[i], sensors[i].T_world_sensor,
                              organised, sensing.streams[i]),
          sensing.pooled_columns[i], params.camera_pooling);
    } else {
      clouds[i] = sim::simulate_frame(caster, sensing.modes[i], sensing.rays[i],
                                      sensors[i].T_world_sensor, settings, sensing.streams[i]);
    }
    points += clouds[i].size();
  }
  return points;
}

// The sensors' points that lie on the moving object (TruthKind::sensor_points), each cloud
// re-cast in its own stamp's scene.
std::vector<model::Vec3> points_on_object(const std::vector<std::unique_ptr<StampedScene>>& scenes,
                                          const std::vector<std::size_t>& scene_of,
                                          const std::vector<model::PointCloud>& clouds,
                                          const OccupancyEvalParams& params) {
  std::vector<std::unique_ptr<sim::RayCaster>> object_casters(scenes.size());
  std::vector<model::Vec3> seen_on_object;
  for (std::size_t i = 0; i < clouds.size(); ++i) {
    const StampedScene& at = *scenes[scene_of[i]];
    std::unique_ptr<sim::RayCaster>& object_caster = object_casters[scene_of[i]];
    if (!object_caster) object_caster = std::make_unique<sim::RayCaster>(at.object);
    const std::vector<model::Vec3> on_object =
        actor_points(clouds[i], at.caster, *object_caster, at.object_box, params.truth_reach);
    seen_on_object.insert(seen_on_object.end(), on_object.begin(), on_object.end());
  }
  return seen_on_object;
}

// One tick's clouds (into `clouds`) and the object's truth points in them.
SensedFrame sense_frame(const model::Scene& scene, std::span<const CellSensor> sensors,
                        std::span<const FrameClock> clocks, double tick, OccupancySensing& sensing,
                        const OccupancyEvalParams& params, std::vector<model::PointCloud>& clouds) {
  const std::vector<double> stamps = sensor_stamps(clocks, sensors.size(), tick);
  std::vector<std::size_t> scene_of;
  const std::vector<std::unique_ptr<StampedScene>> scenes = stamped_scenes(scene, stamps, scene_of);
  SensedFrame frame;
  frame.points = simulate_cell_clouds(scenes, scene_of, sensors, sensing, params, clouds);
  // The set's latest stamp; with no sensor, the tick itself.
  const double fused = stamps.empty() ? tick : *std::max_element(stamps.begin(), stamps.end());
  frame.T_world_object = scene.moving.front().T_world_object(fused);
  frame.object_now.append(scene.moving.front().mesh, frame.T_world_object);
  if (params.truth == TruthKind::sensor_points)
    frame.on_object = points_on_object(scenes, scene_of, clouds, params);
  if (params.truth == TruthKind::link_volumes)
    frame.on_object = points_in_links(clouds, frame.T_world_object, params.object_links);
  return frame;
}

// The truth's object, seen and column masks at this frame.
void refresh_truth(LatticeTruth& truth, const model::TriangleMesh& object_now,
                   const std::vector<model::Vec3>& seen_on_object,
                   const std::vector<model::PointCloud>& clouds,
                   const OccupancyEvalParams& params) {
  truth.object =
      in_scored_band(params.truth == TruthKind::mesh_surface
                         ? voxelise_surface(object_now, truth.lattice, params.min_height)
                         : voxelise_points(seen_on_object, truth.lattice, params.min_height),
                     truth.lattice, params.min_height);
  // Only the object's voxels can be misses, so only marking points inside its x span count.
  truth.seen.clear();
  if (!truth.object.empty()) {
    const auto [low, high] = std::minmax_element(
        truth.object.begin(), truth.object.end(),
        [](const costmap::VoxelKey& a, const costmap::VoxelKey& b) { return a.x < b.x; });
    const int x0 = low->x, x1 = high->x;
    for (const model::PointCloud& cloud : clouds) {
      for (const model::Point3f& p : cloud.points) {
        if (p.z() < params.min_height) continue;  // below the band: clears, never marks
        const costmap::VoxelKey key = truth.lattice.key_at(p.cast<double>());
        if (key.x >= x0 && key.x <= x1) truth.seen.push_back(key);
      }
    }
  }
  std::vector<costmap::VoxelKey> all = truth.scenery;
  all.insert(all.end(), truth.object.begin(), truth.object.end());
  truth.columns = column_mask(all, truth.window);
  truth.dilated = dilate_mask(truth.columns, truth.window, params.robot_radius);
}

// What every mapper is given and scored with at one frame, besides its own truth.
struct OccupancyFrameInputs {
  double t;
  bool moving;
  std::size_t points;
  const std::vector<model::PointCloud>& clouds;
  const HullRegion& hull;
  const PathOdometer& odometer;
};

// The delays of the changes completed at this frame go to the phase it belongs to.
void record_change_delays(ChangeDelays& delays, double t, const LatticeTruth& truth,
                          const std::vector<std::uint8_t>& shown, OccupancyPhase& phase) {
  const std::size_t marks_before = delays.mark_delays().size();
  const std::size_t clears_before = delays.clear_delays().size();
  delays.record(t, truth.columns, shown);
  phase.mark_delays.insert(phase.mark_delays.end(),
                           delays.mark_delays().begin() + static_cast<std::ptrdiff_t>(marks_before),
                           delays.mark_delays().end());
  phase.clear_delays.insert(
      phase.clear_delays.end(),
      delays.clear_delays().begin() + static_cast<std::ptrdiff_t>(clears_before),
      delays.clear_delays().end());
}

// One mapper's update and scores at one frame: they touch only its own state and run, so the
// mappers run in parallel.
void score_mapper_frame(OccupancyMapper& mapper, const LatticeTruth& truth, Tracking& tracking,
                        OccupancyRun& run, const OccupancyFrameInputs& in,
                        const OccupancyEvalParams& params) {
  OccupancyFrame frame;
  frame.time = in.t;
  frame.robot_moving = in.moving;
  frame.points = in.points;
  const auto candidates = [&](const std::vector<costmap::VoxelKey>& shown) {
    return params.region == ScoringRegion::hull ? in_hull(shown, truth, in.hull)
                                                : near_object(shown, truth, params.object_margin);
  };
  frame.object_late = compare_voxel_sets(candidates(tracking.shown_before), truth.object);
  const auto start = std::chrono::steady_clock::now();
  mapper.update(in.t, in.clouds, in.moving);
  frame.update_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<costmap::VoxelKey> predicted =
      in_scored_band(mapper.occupied(), truth.lattice, params.min_height);
  frame.object = compare_voxel_sets(candidates(predicted), truth.object);
  frame.misses = split_misses(predicted, truth.object, truth.seen);
  const std::vector<std::uint8_t> shown = column_mask(predicted, truth.window);
  const TrailFrame trail = tracking.trail.record(in.t, truth.columns, shown);
  frame.ghost_area = trail.ghost_area;
  frame.trail_area = trail.trail_area;
  frame.trail_length =
      std::isnan(trail.trail_p90_time) ? 0.0 : in.odometer.length_since(trail.trail_p90_time);
  frame.trail_length_oldest =
      std::isnan(trail.oldest_trail_time) ? 0.0 : in.odometer.length_since(trail.oldest_trail_time);
  record_change_delays(tracking.delays, in.t, truth, shown,
                       in.moving ? run.moving : run.stationary);
  const std::vector<std::uint8_t> blocked = mapper.blocked_cells(truth.window);
  frame.has_master = !blocked.empty();
  if (frame.has_master) {
    frame.master = compare_masks(blocked, truth.dilated);
    frame.master_ghost_area = ghost_area(blocked, truth.dilated, truth.window.resolution);
  }
  run.frames.push_back(frame);
  tracking.shown_before = std::move(predicted);
}

// The run's phases from its frames, and what the mapper's whole-window measures left pending.
void finish_run(OccupancyRun& run, Tracking& tracking, const OccupancyMapper& mapper) {
  std::vector<const OccupancyFrame*> moving, stationary, all;
  for (const OccupancyFrame& frame : run.frames) {
    (frame.robot_moving ? moving : stationary).push_back(&frame);
    all.push_back(&frame);
  }
  finish_phase(run.moving, moving);
  finish_phase(run.stationary, stationary);
  finish_phase(run.all, all);
  run.all.mark_delays = run.moving.mark_delays;
  run.all.mark_delays.insert(run.all.mark_delays.end(), run.stationary.mark_delays.begin(),
                             run.stationary.mark_delays.end());
  run.all.clear_delays = run.moving.clear_delays;
  run.all.clear_delays.insert(run.all.clear_delays.end(), run.stationary.clear_delays.begin(),
                              run.stationary.clear_delays.end());
  run.pending_changes = tracking.delays.pending();
  run.missed_marks = tracking.delays.missed_marks();
  run.missed_clears = tracking.delays.missed_clears();
  run.memory_bytes = mapper.memory_bytes();
}

}  // namespace

std::vector<CellSensor> cell_sensors(const model::Rig& rig, const model::SensorLibrary& library) {
  std::vector<CellSensor> sensors;
  for (const model::Mount& mount : rig.mounts) {
    sensors.push_back(
        {mount.id, *library.find(mount.sensor_id)->find_mode(mount.mode_id), mount.T_robot_sensor});
  }
  return sensors;
}

std::vector<OccupancyRun> evaluate_occupancy(const model::Scene& scene,
                                             std::span<const CellSensor> sensors,
                                             std::span<OccupancyMapper* const> mappers,
                                             const OccupancyEvalParams& params) {
  if (scene.moving.empty()) {
    throw std::invalid_argument("evaluate_occupancy: the scene '" + scene.name +
                                "' has no moving object");
  }
  const model::MovingObject& object = scene.moving.front();
  if (params.truth == TruthKind::link_volumes && params.object_links.empty()) {
    throw std::invalid_argument("evaluate_occupancy: the truth from link volumes needs '" +
                                object.name + "''s links");
  }
  const int frames = frame_count(params);
  OccupancySensing sensing = occupancy_sensing(sensors, params);
  std::vector<std::size_t> truth_of;
  std::vector<LatticeTruth> truths = lattice_truths(scene, mappers, params, truth_of);
  std::vector<OccupancyRun> runs(mappers.size());
  std::vector<Tracking> tracking;
  for (std::size_t m = 0; m < mappers.size(); ++m) {
    runs[m].mapper = mappers[m]->name();
    runs[m].resolution = truths[truth_of[m]].lattice.resolution;
    const costmap::GridWindow& window = truths[truth_of[m]].window;
    tracking.push_back({TrailTracker(window.size(), window.resolution * window.resolution),
                        ChangeDelays(window.size()),
                        {}});
  }
  PathOdometer odometer;
  std::vector<model::PointCloud> clouds(sensors.size());
  std::vector<FrameClock> clocks;
  if (params.approximate_sync) {
    std::vector<double> frequencies;
    for (const CellSensor& sensor : sensors) frequencies.push_back(sensor.mode.frequency);
    clocks = frame_clocks(frequencies, params.seed);
  }
  for (int k = 0; k < frames; ++k) {
    const double t = k / params.rate;
    const bool moving = t < params.moving_until;
    const SensedFrame sensed = sense_frame(scene, sensors, clocks, t, sensing, params, clouds);
    odometer.record(t, sensed.T_world_object.translation().head<2>());
    const HullRegion hull(params.truth == TruthKind::mesh_surface ? sensed.object_now.vertices
                                                                  : sensed.on_object);
    for (LatticeTruth& truth : truths)
      refresh_truth(truth, sensed.object_now, sensed.on_object, clouds, params);
    const OccupancyFrameInputs inputs{t, moving, sensed.points, clouds, hull, odometer};
    model::parallel_for(mappers.size(), params.threads, [&](std::size_t m) {
      score_mapper_frame(*mappers[m], truths[truth_of[m]], tracking[m], runs[m], inputs, params);
    });
    if (params.progress) params.progress(k + 1, frames);
  }
  for (std::size_t m = 0; m < mappers.size(); ++m) finish_run(runs[m], tracking[m], *mappers[m]);
  return runs;
}

}  // namespace rigdesign::occupancy
