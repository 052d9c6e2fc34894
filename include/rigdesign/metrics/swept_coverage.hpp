#pragma once
/// Swept coverage (issue 38, item 4; docs/swept_coverage.md): what the rig sees while the robot
/// turns in place or drives an arc, where SC is a snapshot. A 220 deg scanner leaves a blind
/// sector behind; turning sweeps it past the cells there, and this says when each cell around
/// the body is first seen and, for the cells the body's outline will run into, whether it is
/// seen at least the stopping time before.
///
/// Model. The rig is cut once per sampled azimuth (the exact path's section polygons): a
/// column standing on the floor at distance rho along azimuth theta, from the floor to the
/// area's top, is seen when any mount sees part of it (the section polygons projected on rho).
/// A point in a robot pose is judged at its robot-frame polar coordinates (rho, theta), theta
/// rounded to the nearest sampled azimuth: an edge of a FOV in azimuth is found to within half
/// the azimuth step. The motion is sampled at a fixed time step chosen so that no cell moves
/// half a cell relative to the robot and the robot turns less than half the azimuth step
/// between samples; a first-seen or reached time is the first sample at which it holds, so it
/// is late by less than one time step. Deterministic.
#include <cstddef>
#include <optional>
#include <vector>

#include "rigdesign/geometry/interval_set.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

/// [m] The cell side when the requirements state no smallest obstacle (R6): 5 cm, the size of
/// a chair leg or a bottle, below what nav2's default 5 cm costmap resolves anyway.
inline constexpr double kDefaultSweepCell = 0.05;

/// Which columns around the robot the rig sees, per sampled azimuth: the rho intervals where a
/// column from the floor to the area's top is seen by at least one mount, out to `distance`.
class VisibilityMap {
 public:
  /// Precondition as compute_coverage; `settings.step` and `settings.tessellation` are used.
  VisibilityMap(const model::Rig& rig, const model::SensorLibrary& library, double distance,
                const CoverageSettings& settings);

  /// The column at robot-frame (rho [m], theta [rad]) is seen; theta is rounded to the nearest
  /// sampled azimuth.
  bool sees(double rho, double theta) const { return seen_[index_of(theta)].contains(rho); }
  /// The body's outline along theta [m] (BodyOccluder::radius_at at the nearest sample).
  double body_radius(double theta) const { return body_radius_[index_of(theta)]; }
  double azimuth_step() const { return step_; }  ///< [rad]
  double distance() const { return distance_; }  ///< [m] how far out columns are judged
  std::size_t azimuth_count() const { return seen_.size(); }
  const geometry::IntervalSet& seen_at(std::size_t azimuth) const { return seen_[azimuth]; }

 private:
  std::size_t index_of(double theta) const;
  double step_ = 0.0;
  double distance_ = 0.0;
  std::vector<double> body_radius_;
  std::vector<geometry::IntervalSet> seen_;
};

enum class SweepKind { rotate, arc };

/// Where the robot is at time t, in the world frame (the robot frame at t = 0).
struct SweepPose {
  model::Vec2 position = model::Vec2::Zero();  ///< [m]
  double heading = 0.0;                        ///< [rad] counter-clockwise from x
};

/// A motion at constant velocities from the world origin, heading along x.
struct SweepMotion {
  SweepKind kind = SweepKind::rotate;
  double turn_rate = 0.0;   ///< [rad/s] rotate: > 0 turns left (counter-clockwise)
  double arc_radius = 0.0;  ///< [m] arc: > 0 turns left, < 0 right; never 0
  double speed = 0.0;       ///< [m/s] arc: forward speed of the robot's centre, > 0

  /// [rad/s] the heading's rate: turn_rate, or speed / arc_radius.
  double angular_rate() const;
  /// [m/s] the centre's speed: 0 turning in place.
  double linear_speed() const { return kind == SweepKind::arc ? speed : 0.0; }
  SweepPose pose_at(double t) const;
};

/// [rad/s] Turning in place with the body's rim (rig.body.radius, the farthest point from the
/// axis) at `speed` [m/s]: the default rate of `--sweep rotate`.
double rim_turn_rate(double speed, const model::RobotBody& body);

/// [s] One full turn (rotate), or the time to drive `distance` [m] along the arc.
double default_horizon(const SweepMotion& motion, double distance);

struct SweepSettings {
  double horizon = 0.0;                               ///< [s] how long the motion runs, > 0
  double cell = kDefaultSweepCell;                    ///< [m] cell side: R6's smallest obstacle
  double deceleration = model::kDefaultDeceleration;  ///< [m/s^2] braking, R5
  CoverageSettings coverage;                          ///< azimuth step and tessellation
};

struct SweepCell {
  model::Vec2 centre = model::Vec2::Zero();  ///< [m] world frame
  std::optional<double> first_seen;          ///< [s] first sample at which the rig sees it
  /// [s] first sample at which the body's outline touches an obstacle of the cell's size
  /// standing on the centre (comes within half a cell of it); nothing for cells the body
  /// touches at t = 0 or never within the horizon.
  std::optional<double> reached;
  /// Reached at or after the stopping time and not seen at least the stopping time before.
  bool late = false;
};

struct SweepRun {
  SweepMotion motion;
  /// Square cells centred on multiples of the cell side, centre within d of the robot's axis
  /// and outside the body's outline at t = 0; row by row (y, then x ascending).
  std::vector<SweepCell> cells;
  double seen_share = 0.0;  ///< of the cells, the share seen at least once within the horizon
  /// [s] when the last cell is first seen; nothing when some cell is never seen.
  std::optional<double> all_seen_time;
  std::size_t swept = 0;  ///< cells the body reaches within the horizon (its swept path)
  /// Of those, reached before the stopping time: no rig could stop for them, not judged.
  std::size_t reached_too_soon = 0;
  std::size_t late = 0;  ///< judged swept cells not seen the stopping time before
  /// The late cell with the least warning (never seen counts least; then the earlier reached).
  std::optional<std::size_t> worst_late;
};

struct SweptCoverage {
  double distance = 0.0;       ///< [m] d: the grid's radius
  double cell = 0.0;           ///< [m]
  double horizon = 0.0;        ///< [s]
  double time_step = 0.0;      ///< [s] between samples of the motion
  double stopping_time = 0.0;  ///< [s] fastest body point's speed / deceleration
  double azimuth_step = 0.0;   ///< [rad] of the visibility map
  /// The body's outline at t = 0 (robot frame), one point per sampled azimuth, for pictures.
  std::vector<model::Vec2> body_outline;
  /// Rotate: turning left, then right; arc: the one motion.
  std::vector<SweepRun> runs;
  std::size_t worst = 0;  ///< the run the summary and the check rest on
  const SweepRun& worst_run() const { return runs[worst]; }
  /// The check: no judged cell of the worst run's swept path is late.
  bool pass() const { return worst_run().late == 0; }
};

/// Swept coverage of `motion` for `settings.horizon` seconds. For rotate, `motion.turn_rate`'s
/// size is run in both directions and the worse run (more late cells, then a later or missing
/// all-seen time, then a smaller seen share) is `worst`. The stopping time is the fastest body
/// point's speed over the deceleration: speed for an arc, turn rate x rig.body.radius turning.
/// Throws InputError (no file) for a motion or settings out of range, or a sweep needing more
/// than kMaxSweepSamples cell samples. Precondition as compute_coverage.
SweptCoverage swept_coverage(const model::Rig& rig, const model::SensorLibrary& library,
                             const SweepMotion& motion, const SweepSettings& settings);

/// Cells x time samples a sweep may take (about a minute on one core): beyond it a longer
/// horizon or a finer grid is refused rather than run for hours.
inline constexpr double kMaxSweepSamples = 2e9;

}  // namespace rigdesign::metrics
