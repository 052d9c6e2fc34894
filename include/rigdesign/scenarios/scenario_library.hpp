#pragma once
/// The bundled robot-in-the-loop scenarios: a scene, a start pose and a route, and the costmap
/// settings they start from.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/costmap/path_follower.hpp"
#include "rigdesign/model/scene.hpp"

namespace rigdesign::scenarios {

/// A point of the route; the robot waits `wait` [s] on arriving there.
struct RouteStop {
  model::Vec2 position = model::Vec2::Zero();  ///< [m] world
  double wait = 0.0;                           ///< [s]
  std::string name;                            ///< for reports; empty: "stop N"
};

/// A floor opening (stairwell, hole) the robot falls into when its centre passes over it:
/// the ground truth of "drove off".
struct FloorDrop {
  std::string name;
  model::Vec2 low = model::Vec2::Zero();   ///< [m] world, corner with the lower x and y
  model::Vec2 high = model::Vec2::Zero();  ///< [m] world
  bool contains(const model::Vec2& p) const {
    return p.x() > low.x() && p.x() < high.x() && p.y() > low.y() && p.y() < high.y();
  }
};

/// A scene, where the robot starts and the route it drives.
struct ScenarioDefinition {
  std::string name;
  std::string description;
  model::Scene scene;
  costmap::Pose2 start;
  std::vector<RouteStop> route;  ///< driven in order; the last stop is the goal
  double max_duration = 60.0;    ///< [s] the run ends here if the goal is not reached
  std::vector<FloorDrop> drops;  ///< openings in the floor
  /// A stop found unreachable (deadlock recoveries exhausted) is skipped and the robot goes on
  /// to the next, as a robot given a list of goals does; false: the run ends there.
  bool skip_unreachable = false;
  /// The scenario's own sensing settings, applied by apply_scenario_settings: the lowest
  /// height that marks (its low obstacles' tops) and ray strides (its thin obstacles' widths).
  std::optional<double> min_obstacle_height;
  std::optional<int> camera_decimation;
  std::optional<int> lidar_decimation;
  /// Paper 2's negative-obstacle stage in the robot's pipeline (ScenarioParams).
  std::optional<bool> negative_obstacles;
};

/// "wall_following" (paper 1 Fig. 12), "stationary" (the motion condition) and "office_goals"
/// (paper 2's goal reaching: sim/office_goals_scene.hpp).
const std::vector<std::string>& costmap_scenario_names();

/// Builds a named scenario with its scene (seeded like make_scene), laid out for a robot of
/// `body_radius` [m]: its lane keeps the robot's side 0.15 m from the followed wall (paper 1's
/// UR Cleaner, r = 0.45 m, drives 0.6 m from it), so the foam and the cart reach as far into
/// any robot's path. Throws std::invalid_argument for an unknown name (the CLI checks names
/// first).
ScenarioDefinition make_costmap_scenario(const std::string& name, std::uint64_t seed,
                                         double body_radius);

/// The door gap [m] office_goals leaves for a robot of `body_radius`: its width plus 0.25 m,
/// so a robot that keeps 5 cm from what it sees passes it and one that keeps 20 cm does not
/// (paper 2: the Kinect's smaller critical distance reached goals behind nearly closed
/// doors); at most the door's full opening.
double office_door_gap(double body_radius);

/// The costmap a scenario starts from: nav2's local costmap (5 cm cells) on a 6 x 6 m window,
/// the 2D obstacle layer (paper 1's setup), the Hit Layer on with paper 1's values.
costmap::CostmapParams scenario_costmap_defaults();

/// nav2's source defaults except min_obstacle_height = 0.10 m: the Azure Kinect's 17 mm range
/// noise puts about one floor return in a thousand above 5 cm, a few per frame, and the 2D
/// layer never clears them (floor returns lie below the band). 10 cm is 6 sigma.
costmap::ObservationSource scenario_source_defaults();

}  // namespace rigdesign::scenarios
