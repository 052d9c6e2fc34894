#pragma once
/// One frame of a robot-in-the-loop run (issue 6 item 3), PNG or SVG by extension: the master
/// grid's costs, the cells only the Hit Layer still holds, the ground truth's outlines in the
/// body's height band, each sensor's horizontal field of view, the planned path, the driven
/// trail and the robot's body. North up, world x to the right, equal scale.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/costmap/path_follower.hpp"
#include "rigdesign/costmap/rolling_grid.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::render {

/// A sensor's horizontal field of view as a wedge on the floor (a disc when it spins).
struct FovWedge {
  model::Vec2 apex = model::Vec2::Zero();  ///< [m] world
  double yaw = 0.0;                        ///< [rad] optical axis
  double half_angle = 0.0;                 ///< [rad]; >= pi draws a disc
  double range = 0.0;                      ///< [m]
  std::size_t colour = 0;                  ///< index into sensor_colour
  std::string label;                       ///< "mount: sensor", for the legend
};

/// Each mount's horizontal view on the floor with the robot at `pose`, as far as the nearer of
/// its mode's range and the mount's marking range (`marking_ranges`, in mount order).
std::vector<FovWedge> fov_wedges(const model::Rig& rig, const model::SensorLibrary& library,
                                 const costmap::Pose2& pose,
                                 std::span<const double> marking_ranges);

struct CostmapFrame {
  std::string title;
  const costmap::CostGrid* master = nullptr;  ///< the grid to draw (not owned)
  /// Cells, on the master's window, the Hit Layer keeps lethal while the obstacle grid does
  /// not see them (row-major; empty for none).
  std::vector<std::uint8_t> remembered;
  std::vector<std::vector<model::Vec2>> obstacles;  ///< ground-truth outlines [m]
  std::vector<FovWedge> fovs;
  std::vector<model::Vec2> path;   ///< planned [m]
  std::vector<model::Vec2> trail;  ///< driven so far [m]
  model::Vec2 robot = model::Vec2::Zero();
  double yaw = 0.0;
  double robot_radius = 0.0;  ///< the collision check's circumscribed cylinder, outlined
  /// The body's real outline in the robot frame (counter-clockwise), filled at the robot's pose;
  /// empty: a round body, filled as its radius.
  std::vector<model::Vec2> footprint;
  bool collided = false;  ///< draws the body in red
};

/// Writes the frame at `pixels_per_cell` pixels per grid cell (at least 1) atomically.
void draw_costmap_frame(const CostmapFrame& frame, const std::string& path,
                        int pixels_per_cell = 4);

}  // namespace rigdesign::render
