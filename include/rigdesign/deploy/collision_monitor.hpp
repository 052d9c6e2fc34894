#pragma once
/// The rig's nav2 collision monitor (issue 34): a stop zone and a slowdown zone ahead of the
/// robot, sized from the robot's speed, its braking deceleration and its sources' latencies,
/// each fed by the sources that see it (deploy/zone_visibility.hpp), with the boundary arcs
/// that no source sees. The sources are the costmap's, on the same topics (self-filtered where
/// the sensor sees its robot) with the same height bands, so one rule decides what marks the
/// costmap and what stops the robot. nav2's parameter names and defaults are cited in
/// data/ros_parameters/nav2_collision_monitor.yaml.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/zone_visibility.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

/// [Hz] nav2 controller_server's default controller_frequency (nav2_controller/src/
/// controller_server.cpp:51 humble, :52 jazzy): the collision monitor judges each velocity
/// command, so a stop waits up to one command period.
inline constexpr double kControllerFrequency = 20.0;
/// nav2's default slowdown_ratio and trigger count (data/ros_parameters/
/// nav2_collision_monitor.yaml): a zone acts on its fourth point, so one stray return does not
/// stop the robot.
inline constexpr double kSlowdownRatio = 0.5;
inline constexpr int kMinPoints = 4;

/// One costmap source feeding the collision monitor.
/// [m] the farthest a generated zone may reach ahead: beyond it the inputs (a throttle far
/// below 1 Hz, a deceleration near zero) are refused rather than measured.
inline constexpr double kMaxZoneReach = 1000.0;

struct CollisionSource {
  std::size_t source = 0;    ///< index into CostmapConfig::sources
  double latency = 0.0;      ///< [s] from an obstacle crossing a zone's edge to the stop
  std::string latency_rule;  ///< its parts, with numbers
  /// [m] above the floor: the heights whose points it passes (the costmap source's band; a
  /// LaserScan passes all).
  double min_z = 0.0;
  double max_z = 0.0;
};

struct ProtectiveZone {
  std::string name;                  ///< the polygon's name in the file
  std::string action;                ///< nav2's action_type: stop or slowdown
  double reach = 0.0;                ///< [m] ahead of the footprint's front
  std::string sizing;                ///< the formula with its numbers
  std::vector<model::Vec2> points;   ///< counter-clockwise, robot frame [m]
  std::vector<std::size_t> sources;  ///< indices into CollisionMonitor::sources seeing it
  ZoneVisibility visibility;         ///< per CollisionMonitor::sources
  int min_points = kMinPoints;       ///< points inside that trigger the action
  std::string min_points_rule;
};

struct CollisionMonitor {
  std::string distro;      ///< humble or jazzy: how the file writes points and sources
  std::string base_frame;  ///< the costmap's robot_base_frame
  /// base_frame in the robot frame: the file's points and heights are in base_frame.
  model::Pose3 T_robot_base = model::Pose3::Identity();
  double speed = 0.0;         ///< [m/s]
  double deceleration = 0.0;  ///< [m/s^2]
  std::string deceleration_from;
  double latency = 0.0;  ///< [s] the slowest source's, which sizes both zones
  double slowdown_ratio = kSlowdownRatio;
  std::vector<CollisionSource> sources;  ///< one per costmap source, in order
  std::vector<ProtectiveZone> zones;     ///< stop first, then slowdown
  std::vector<std::string> notes;
};

/// What sizes the zones beyond the requirements: `processing_latency` [s] is the driver's
/// and filters' time per frame (nothing: one frame period, the most a chain that keeps up with
/// its sensor can take).
struct CollisionMonitorOptions {
  std::string distro = "jazzy";
  double speed = 0.0;  ///< [m/s]; 0: the requirements' R5 speed
  std::optional<double> processing_latency;
};

/// Nothing when no speed is known (neither options.speed nor requirements R5). Precondition:
/// `config` was made for `rig` (one source per mount, in order).
std::optional<CollisionMonitor> collision_monitor(const model::Rig& rig,
                                                  const model::SensorLibrary& library,
                                                  const model::Requirements* requirements,
                                                  const CostmapConfig& config,
                                                  const CollisionMonitorOptions& options);

/// The robot's outline as the collision monitor and nav2's footprint take it.
BodyOutline body_outline(const CostmapConfig& config);

}  // namespace rigdesign::deploy
