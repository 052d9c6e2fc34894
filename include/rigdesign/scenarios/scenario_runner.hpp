#pragma once
/// The robot in the loop (issue 6 item 2; paper 1 section 4, Fig. 12): a rig's sensors are
/// simulated in a scene at the robot's pose, the costmap takes their clouds, Dijkstra plans
/// on its master grid towards a goal along a route, a pure-pursuit follower drives the
/// body, and every control step checks the body against the scene's ground-truth triangles.
/// Deterministic for a seed.
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/costmap/dijkstra_planner.hpp"
#include "rigdesign/costmap/dwa_planner.hpp"
#include "rigdesign/costmap/path_follower.hpp"
#include "rigdesign/model/filter_params.hpp"
#include "rigdesign/model/filtering_loads.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/scene.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/scenarios/scenario_library.hpp"
#include "rigdesign/scenarios/sensor_timing.hpp"

namespace rigdesign::scenarios {

/// What turns the global plan into velocity commands.
enum class LocalPlanner { pure_pursuit, dwa };

struct ScenarioParams {
  /// robot_radius and the inscribed radius are set from the rig's body; the inflation radius
  /// is raised to inscribed + 0.1 m when smaller; the voxel band's top to the body's height.
  costmap::CostmapParams costmap = scenario_costmap_defaults();
  /// Where the window's size was set: a parameter file's width; empty: the command line.
  model::SourceLocation window_where;
  /// Per-mount source settings; max_obstacle_height is set to the body's height (nav2 practice:
  /// points above the robot neither mark nor clear).
  costmap::ObservationSource source = scenario_source_defaults();
  /// Per-mount source settings by mount id, as a nav2 file's observation_sources name them;
  /// used as given. A mount without an entry uses `source`.
  std::vector<costmap::NamedObservationSource> mount_sources;
  costmap::PlannerParams planner;
  costmap::FollowerParams follower;
  /// Pure pursuit (the default) or paper 2's DWA, whose speed limits are the follower's.
  LocalPlanner local_planner = LocalPlanner::pure_pursuit;
  costmap::DwaParams dwa;
  /// Paper 2's deadlock handling: stuck (no plan, or no admissible DWA velocity) for
  /// `deadlock_patience` [s], stop, clear the costmap beyond `deadlock_clear_radius` [m] and
  /// turn 360 deg on the spot; stuck again before the next route stop, clear it entirely and
  /// turn again; a third time, give up (the goal is unreachable). The patience is ours (paper
  /// 2 gives none): 2 s, ten costmap updates.
  bool deadlock_recovery = true;
  double deadlock_patience = 2.0;
  double deadlock_clear_radius = 0.5;
  double update_rate = 5.0;    ///< [Hz] sensing, costmap update and planning
  double control_rate = 20.0;  ///< [Hz] follower commands and collision checks
  /// The control loop steps at most this many times between two costmap updates (a minute at
  /// 20 Hz): slower, the robot drives blind for longer than a scenario's legs take, and an
  /// update rate of 1e-300 Hz overflowed the step count (issue 53 item 3).
  static constexpr double kMaxStepsPerUpdate = 1200.0;
  /// [Hz] the slowest update rate a run takes.
  double min_update_rate() const { return control_rate / kMaxStepsPerUpdate; }
  double goal_lookahead = 2.0;   ///< [m] local goal distance along the route (capped by the window)
  double goal_tolerance = 0.15;  ///< [m] a stop counts as reached within this distance
  /// [m] a local goal on a blocked cell moves to the nearest passable cell this close to it.
  double goal_search_radius = 1.0;
  double ground_clearance = 0.02;  ///< [m] bottom of the body's height band (the floor is not hit)
  /// Strides of sim::decimated_mode: every k-th pixel row and column of cameras (an Azure
  /// Kinect frame has 368,640 rays), every k-th ray along the scan of lidars and scanners;
  /// the tests' and default runs' speed. 1 casts every ray.
  int camera_decimation = 8;
  int lidar_decimation = 4;
  bool add_noise = true;  ///< range noise per sensor model
  /// Cameras with depth_matching report the depth filling most of each pixel's window
  /// (sim/depth_matching.hpp); false: every ray its own first hit.
  bool depth_matching = true;
  std::uint64_t seed = 1;  ///< sensor noise streams and frame phases
  /// Sensors as they run (sensor_timing.hpp): each mount captures at its own rate and its
  /// frame reaches the costmap a latency later; the filters' share of that latency is this
  /// many core-seconds per point, or the sensor's measured figure in `filtering_loads`.
  double filtering_seconds_per_point = kPaperFilteringSecondsPerPoint;
  const model::FilteringLoads* filtering_loads = nullptr;
  /// The filters' core-seconds per point for a sensor: its measured figure in
  /// `filtering_loads`, else `filtering_seconds_per_point`.
  double seconds_per_point(const std::string& sensor_id) const;
  /// [s] each mount's first capture, in mount order; empty: drawn from the seed.
  std::vector<double> frame_phases;
  /// [m] added to the body's radius where the costmap inflates (nav2's footprint_padding): how
  /// close the planners let the robot come to what the sensors see. The ground-truth collision
  /// check keeps the body's own radius. The critical-distance sweep varies it.
  double clearance_margin = 0.0;
  /// Paper 2's negative obstacles on every frame before the costmap (filters::
  /// mark_negative_obstacles: returns below -2 cm mirrored, a virtual point 10 cm up where the
  /// ray crossed the floor), so a stairwell a sensor looks into is marked at its edge. Off by
  /// default: a sensor whose floor returns scatter past 2 cm (the Azure Kinect's 17 mm at a
  /// steep angle) marks drops on flat floor, as the stage would on the robot without noise
  /// removal before it; scenarios with drops turn it on (apply_scenario_settings).
  bool negative_obstacles = false;
  /// Paper 2's "points with too few neighbours removed" (filters::radius_outlier_removal) on
  /// every camera frame before the costmap; nothing: off. The 2D scanner's scan reaches the
  /// costmap as a LaserScan, which the point-cloud stage does not see (our reading of paper 2's
  /// section 3.2). With a camera ray stride k the radius is taken k times larger, which keeps a
  /// point's neighbour count on a surface what it is at full resolution (k^2 fewer points per
  /// area, k^2 more area).
  std::optional<model::RadiusOutlierParams> camera_radius_outlier;
  /// False: frames reach the costmap the moment they are captured (no driver or filter time),
  /// the idealised loop in which, with phases 0 and rates that are multiples of the update
  /// rate, every update sees the world as it is at that update.
  bool model_latency = true;
};

/// A scenario's own sensing settings (ScenarioDefinition's min_obstacle_height and ray
/// strides), written into `params` where the scenario sets them; mount sources named by a
/// parameter file keep theirs.
void apply_scenario_settings(const ScenarioDefinition& scenario, ScenarioParams& params);

/// What became of one route stop.
struct StopOutcome {
  std::string name;
  bool reached = false;
  double reached_time = 0.0;  ///< [s]
  /// Found unreachable (recoveries exhausted) and skipped; `reason` says why.
  bool refused = false;
  std::string reason;
  double leg_distance = 0.0;  ///< [m] driven since the previous stop ended
  double leg_seconds = 0.0;   ///< [s] and how long it took (waits at stops excluded)
};

/// A sampled pose of the run.
struct TrajectorySample {
  double time = 0.0;  ///< [s]
  costmap::Pose2 pose;
};

/// What one costmap update saw and decided, for drawing and tests (valid during the callback).
struct ScenarioStep {
  int index = 0;                  ///< update number from 0
  double time = 0.0;              ///< [s]
  costmap::Pose2 pose;            ///< robot pose at the update
  bool velocity_command = false;  ///< the command given to the costmap's motion condition
  bool waiting = false;           ///< the robot stands at a stop
  const costmap::Costmap* costmap = nullptr;
  const costmap::PlannedPath* path = nullptr;  ///< the plan of this update (empty while waiting)
  model::Vec2 goal = model::Vec2::Zero();      ///< the local goal planned to [m]
  /// The newest frame the costmap holds of each mount, world frame, one per mount (empty before
  /// its first frame arrives).
  std::span<const model::PointCloud> clouds;
  /// Each moving object's own clock [s] (scene.moving order): the time to pose it at, behind
  /// the scene's for one that gave way to the robot.
  std::span<const double> object_clocks;
};

struct ScenarioResult {
  bool collided = false;
  double collision_time = std::numeric_limits<double>::quiet_NaN();  ///< [s] first contact
  std::string collision_object;                                      ///< scene object hit
  model::Vec2 collision_position = model::Vec2::Zero();              ///< robot centre [m]
  /// [m] smallest body clearance over the run (negative: penetration at the collision step).
  double min_clearance = std::numeric_limits<double>::infinity();
  double min_clearance_time = 0.0;  ///< [s]
  std::string min_clearance_object;
  bool reached_goal = false;
  double end_time = 0.0;  ///< [s] goal, collision or max_duration
  int updates = 0;
  int planner_failures = 0;       ///< updates whose plan found no path (the robot held still)
  int dwa_blocked_steps = 0;      ///< control steps at which DWA found no admissible velocity
  int recoveries = 0;             ///< deadlock recoveries started
  double recovery_seconds = 0.0;  ///< [s] spent turning in them
  bool gave_up = false;           ///< recoveries exhausted: the goal is unreachable
  std::string gave_up_reason;
  std::vector<StopOutcome> stops;  ///< one per route stop tried, in route order
  std::size_t route_size = 0;      ///< the scenario's stops
  int goals_reached = 0;
  /// The robot's centre passed over a floor drop: it drove off (the run ends there).
  bool drove_off = false;
  std::string drop_name;
  double drove_off_time = 0.0;   ///< [s]
  double drove_off_speed = 0.0;  ///< [m/s] commanded at the edge
  /// A walker touched the robot while it stood still (not the robot's collision; counted).
  int struck_while_standing = 0;
  double distance = 0.0;  ///< [m] driven over the run
  /// [m/s] distance over time on the legs to stops reached (paper 2's average speed); 0 when
  /// none was reached.
  double average_speed = 0.0;
  std::vector<TrajectorySample> trajectory;  ///< one sample per costmap update and the last pose
  std::vector<double> update_seconds;        ///< wall time of each Costmap::update [s]
  std::vector<double> planner_seconds;       ///< wall time of each plan [s]
  std::vector<MountTiming> timings;          ///< per simulated mount, in mount order
  int frames_cast = 0;                       ///< frames simulated over the run
};

/// Throws InputError at the rig's `mounts` (file:line:column) when no mount can mark: none
/// of its rays reaches the costmap's height band within the marking range, or the rig has no
/// mounts; at the rig's `body` when its radius or height is not positive. Also checks the
/// costmap parameters (InputError, fields as in check_costmap_params, at `where`).
void check_scenario_inputs(const model::Rig& rig, const model::SensorLibrary& library,
                           const ScenarioParams& params,
                           const model::SourceLocation& where = model::SourceLocation{
                               "(command line)"});

/// The source each mount of `rig` marks and clears with, in mount order: its entry in
/// params.mount_sources, else params.source with max_obstacle_height at the body's height.
std::vector<costmap::ObservationSource> mount_sources_of(const model::Rig& rig,
                                                         const ScenarioParams& params);

/// Runs the scenario with `rig`'s sensors (modes from `library`) on a body of the rig's
/// radius and height. Checks its inputs first (check_scenario_inputs). `on_update` is called
/// after every costmap update and plan. The run stops at the first collision, at the goal or
/// at max_duration. Deterministic for params.seed, except the measured times.
ScenarioResult run_scenario(const ScenarioDefinition& scenario, const model::Rig& rig,
                            const model::SensorLibrary& library, const ScenarioParams& params,
                            const std::function<void(const ScenarioStep&)>& on_update = {});

/// model::median and the 99th model::percentile of durations [s]; zeros when empty.
struct TimeSummary {
  double median = 0.0;
  double p99 = 0.0;
};
TimeSummary summarize_times(const std::vector<double>& seconds);

}  // namespace rigdesign::scenarios
