#pragma once
/// Paper 3's occupancy evaluation on a scene with a moving object (issue 6, DESIGN.md
/// section 7), and the whole-grid view paper 3 lacks. Fixed sensors record every frame at the
/// evaluation rate; every mapper gets the same frames; each frame is scored
/// - near the object, as paper 3: voxels shown within `object_margin` of the object's box
///   (static scenery left out) against the object's surface voxels -> P, R, F1, F2, F3;
/// - over the whole window: ghost area (columns shown occupied where nothing is), the trail
///   behind the object, time to mark and to clear a cell, misses split by cause;
/// - the planner's 2D grid against the truth's columns dilated by the robot's radius;
/// separately for the phases where the robot counts as moving and where it stands still.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/model/progress.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/scene.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/occupancy/occupancy_scores.hpp"
#include "rigdesign/occupancy/occupancy_voxel_mapper.hpp"
#include "rigdesign/sim/person_links.hpp"

namespace rigdesign::occupancy {

/// A fixed sensor of the cell.
struct CellSensor {
  std::string id;
  model::SensorMode mode;
  model::Pose3 T_world_sensor = model::Pose3::Identity();
};

/// The rig's mounts as cell sensors: the cell's sensors are fixed, so the rig's robot frame
/// is the cell (world) frame. Every mount's sensor and mode must be in `library`.
std::vector<CellSensor> cell_sensors(const model::Rig& rig, const model::SensorLibrary& library);

/// What the scored object's truth voxels are.
enum class TruthKind {
  /// Paper 3 as paper 3 finds them (section III-B, eqs. 1-4): the fused clouds' points inside
  /// the volumes round the object's links (occupancy_link_volumes.hpp,
  /// OccupancyEvalParams::object_links), voxelised.
  link_volumes,
  /// The object's points in the sensors' own clouds found by a noise-free re-cast of each
  /// point's ray (occupancy_actor_points.hpp): what the sensors saw of it this frame, nothing
  /// off its surface.
  sensor_points,
  /// The voxels of the object's whole mesh surface, its unseen back included: the project's
  /// earlier truth, kept as a labelled alternative (a miss there may be a coverage gap).
  mesh_surface,
};

/// Where a shown voxel that is not in the truth counts as a false positive.
enum class ScoringRegion {
  /// Paper 3 (section III-C): inside the convex hull of the object's points (its truth points:
  /// the sensors' points on it, or its mesh's vertices with TruthKind::mesh_surface), a voxel
  /// counted when its centre lies within half a voxel side of the hull.
  hull,
  /// The project's earlier region: within object_margin (x, y) of the truth voxels' box.
  box_margin,
};

struct OccupancyEvalParams {
  double rate = 5.0;       ///< [Hz] frames per second; every sensor records each frame
  double duration = 96.0;  ///< [s] paper 3: two laps of the ellipse in about 96 s
  /// [s] the robot counts as moving (velocity command on) before this time and standing still
  /// after: the first lap shows the Hit Layer's decay, the second its keeping everything.
  double moving_until = 48.0;
  std::uint64_t seed = 1;      ///< range noise; each sensor draws from (seed, sensor index)
  double object_margin = 0.3;  ///< [m] paper 3's neighbourhood of the object, in x and y
  TruthKind truth = TruthKind::sensor_points;
  /// The object's links and their volumes, in its own frame (TruthKind::link_volumes).
  std::vector<sim::BodyLink> object_links;
  ScoringRegion region = ScoringRegion::hull;
  /// [m] how far from the object's box a point may lie and still be re-cast as the object's:
  /// 5 sigma of the cell's noisiest sensors (3 cm), since noise moves points along their rays.
  double truth_reach = 0.15;
  /// [m] truth voxels start here; set the mappers' min_obstacle_height to the same. 0.1 m is
  /// 3 sigma of the cell's noisiest lidars (3 cm): lower, and noisy floor returns mark ghosts.
  double min_height = 0.1;
  double window_size = 6.0;   ///< [m] the scored square, centred on the world origin
  double robot_radius = 0.3;  ///< [m] the truth's dilation for the planner's grid
  /// sim::decimated_mode's camera stride (1: every pixel): ray casting a full camera frame is
  /// the evaluation's slowest step. Lidars are never decimated.
  int camera_stride = 1;
  /// Paper 3's downsampling of its RGB-D camera (section III-B): mean pooling of k x k pixel
  /// blocks of the organised depth image (sim/mean_pooling.hpp); 1 keeps every pixel. Applies
  /// to cameras whose ray pattern is a full pixel grid (pyramid FOVs).
  int camera_pooling = 1;
  /// Paper 3's approximate-time fusion (approximate_sync.hpp): each sensor records at its own
  /// frequency from a phase drawn from `seed`, and each tick takes the set ROS's filter would
  /// have paired by then; the object's truth uses its pose at the set's latest stamp. false:
  /// every sensor records at the tick.
  bool approximate_sync = false;
  /// Mappers updated and scored at once within a frame (their results do not depend on it).
  int threads = 1;
  /// Called after every frame with (frames done, frames in all).
  model::ProgressCallback progress;
};

/// One frame of one mapper.
struct OccupancyFrame {
  double time = 0.0;  ///< [s]
  bool robot_moving = false;
  std::size_t points = 0;       ///< points of every sensor this frame
  double update_seconds = 0.0;  ///< [s] the mapper's update, one thread
  ConfusionCounts object;       ///< paper 3's counts near the object
  /// The same truth against the map as it stood before this frame's update: the map read one
  /// update late, as when a mapper's output lags its input (paper 3 read "the first map
  /// message after the fused clouds' latest stamp").
  ConfusionCounts object_late;
  MissCauses misses;        ///< the object's false negatives by cause
  double ghost_area = 0.0;  ///< [m^2]
  double trail_area = 0.0;  ///< [m^2]
  /// [m] of the object's path 90 % of the trail's cells reach back over (trail_p90_time)
  double trail_length = 0.0;
  double trail_length_oldest = 0.0;  ///< [m] back to the trail's oldest cell (stale ones too)
  bool has_master = false;           ///< the mapper feeds a planner's grid
  ConfusionCounts master;            ///< blocked cells vs truth columns dilated by robot_radius
  double master_ghost_area = 0.0;    ///< [m^2] blocked cells outside the dilated truth
};

/// Means over the frames of one phase.
struct OccupancyPhase {
  std::size_t frames = 0;
  Scores object;       ///< mean of the per-frame scores (paper 3)
  Scores object_late;  ///< the same with the map read one update late
  Scores master;
  double ghost_area = 0.0;           ///< [m^2] mean
  double ghost_area_max = 0.0;       ///< [m^2]
  double trail_area = 0.0;           ///< [m^2] mean: columns the person left, still shown
  double trail_length = 0.0;         ///< [m] mean
  double trail_length_max = 0.0;     ///< [m]
  double master_ghost_area = 0.0;    ///< [m^2] mean
  std::size_t never_seen = 0;        ///< summed object misses no sensor saw
  std::size_t seen_not_kept = 0;     ///< summed object misses seen but not kept
  std::vector<double> mark_delays;   ///< [s] resolved during the phase
  std::vector<double> clear_delays;  ///< [s] resolved during the phase
  double update_ms = 0.0;            ///< mean update time [ms]
  double points_per_second = 0.0;    ///< points inserted per second of update time
};

struct OccupancyRun {
  std::string mapper;
  double resolution = 0.0;  ///< [m]
  std::vector<OccupancyFrame> frames;
  OccupancyPhase moving;
  OccupancyPhase stationary;
  OccupancyPhase all;
  std::size_t pending_changes = 0;  ///< truth changes the grid had not followed at the end
  std::size_t missed_marks = 0;
  std::size_t missed_clears = 0;
  std::size_t memory_bytes = 0;  ///< the mapper's storage after the last frame
};

/// Runs every mapper on the same frames of `scene` (its first moving object is the scored
/// object; the robot frame is the world frame) and scores them. Deterministic for a seed
/// except the update times. Throws std::invalid_argument when the scene has no moving object.
std::vector<OccupancyRun> evaluate_occupancy(const model::Scene& scene,
                                             std::span<const CellSensor> sensors,
                                             std::span<OccupancyMapper* const> mappers,
                                             const OccupancyEvalParams& params);

}  // namespace rigdesign::occupancy
