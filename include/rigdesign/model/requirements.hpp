#pragma once
/// Application requirements R1-R8 of paper 1 (section 2.1; DESIGN.md section 5). They are
/// stated in the application's terms (speed, obstacle size, lighting); the satisficing
/// metrics SC, F, R, N, L are derived from them, never written directly.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

/// R2: a direction of motion and the spatial coverage it needs.
struct SectorRequirement {
  std::string name;
  double from = 0.0;                   ///< [rad] azimuth, counter-clockwise from x (forward)
  double to = 0.0;                     ///< [rad] to > from; the sector may wrap past 180 degrees
  double min_complete_coverage = 0.0;  ///< SC complete, share in [0, 1]
  double min_floor_coverage = 0.0;     ///< SC floor, share in [0, 1]
  SourceLocation where;
};

/// A speed and how far things may move between two frames: needs F >= speed / travel.
struct MotionBetweenFrames {
  double speed = 0.0;   ///< [m/s]
  double travel = 0.0;  ///< [m]
  SourceLocation where;
  double min_frequency() const { return speed / travel; }
};

/// Robustness (issue 15): the failures a rig must survive, and the sector thresholds it must
/// still meet after each (its own sectors' unless relaxed here by name).
struct RobustnessRequirement {
  bool single_failure = false;              ///< `n-1`: any one sensor failing
  std::optional<LightCondition> condition;  ///< every sensor not immune to it failing at once
  /// Relaxed thresholds by sector name (from/to unused: the named sector's angles apply).
  std::vector<SectorRequirement> sectors;
  SourceLocation where;
  bool any() const { return single_failure || condition.has_value(); }
};

/// Target-free extrinsic calibration needs sensors that see common structure (issue 38, item
/// 3): the co-visible area of two mounts (model in metrics/covisibility.hpp) must reach
/// `min_overlap` for the pair to count, and the graph of such pairs must be connected (every
/// mount calibrated to every other through a chain) or, with `all_pairs`, complete.
struct CalibrationRequirement {
  double min_overlap = 0.0;  ///< [m^2]
  bool all_pairs = false;
  SourceLocation where;
};

/// [m/s^2] The deceleration assumed when a requirements file states none: nav2's own default
/// braking limit, velocity_smoother `max_decel` = -2.5 m/s^2 (nav2_velocity_smoother/src/
/// velocity_smoother.cpp:71 at humble 3c3db59 and jazzy f4108e5), which TurtleBot 4's nav2.yaml
/// keeps. A base that brakes more gently needs larger polygons: state yours.
inline constexpr double kDefaultDeceleration = 2.5;

struct Requirements {
  std::string name;
  // R1: body size and the area to perceive.
  std::optional<double> body_radius;  ///< [m]
  std::optional<double> body_height;  ///< [m]
  SourceLocation body_where;
  /// Top of the area to perceive [m]; the body's height when not stated.
  std::optional<double> area_height;
  SourceLocation area_height_where;
  /// What the loader noticed that is not an error (a sector that looks like radians).
  std::vector<Diagnostic> load_warnings;
  // R2: directions of motion.
  std::vector<SectorRequirement> sectors;
  // R3: range and a rate the application needs regardless of motion.
  double distance = 0.0;                ///< d [m]
  std::optional<double> min_frequency;  ///< [Hz]
  SourceLocation range_where;
  // R4: object dynamics; R5: robot speed.
  std::optional<MotionBetweenFrames> object_dynamics;
  std::optional<MotionBetweenFrames> robot_speed;
  /// [m/s^2] how hard the robot brakes from its speed to a stop (`robot_speed.deceleration`):
  /// sizes the collision monitor's stop and slowdown polygons (deploy/collision_monitor.hpp).
  /// Not stated: kDefaultDeceleration.
  std::optional<double> deceleration;
  SourceLocation deceleration_where;
  // R6: smallest obstacle to notice at distance d.
  std::optional<double> smallest_obstacle;  ///< [m]
  SourceLocation smallest_obstacle_where;
  // R7: accuracy.
  std::optional<double> max_noise;  ///< [m] one sigma at distance d
  SourceLocation accuracy_where;
  // R8: lighting conditions the rig must work in.
  std::vector<LightCondition> lighting;
  SourceLocation lighting_where;
  std::optional<RobustnessRequirement> robustness;
  std::optional<CalibrationRequirement> calibration;

  std::string file;

  /// Satisficing frequency: the largest of R3's rate, R4's and R5's v / travel [Hz].
  double required_frequency() const;
  /// The stated deceleration, else kDefaultDeceleration [m/s^2].
  double braking_deceleration() const { return deceleration.value_or(kDefaultDeceleration); }
};

}  // namespace rigdesign::model
