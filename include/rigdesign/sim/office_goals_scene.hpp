#pragma once
/// Paper 2's office for goal reaching (issue 35 item 2): desks on thin legs with office chairs
/// whose star bases reach past their columns, a side room behind a door left ajar, two people
/// walking across the room, and a stairwell down on the way to the last goal.
#include <cstdint>
#include <string>
#include <vector>

#include "rigdesign/model/scene.hpp"
#include "rigdesign/sim/mesh_primitives.hpp"

namespace rigdesign::sim {

/// A place the robot is sent to, by name.
struct NamedPlace {
  std::string name;
  model::Vec2 position = model::Vec2::Zero();  ///< [m] world
};

/// An opening in the floor the robot would fall into (ground truth for "drove off").
struct FloorOpening {
  std::string name;
  Rect2 area;  ///< [m] world, z = 0
};

struct OfficeGoalsLayout {
  model::Scene scene;  ///< T_world_robot: the start, facing +x
  std::vector<NamedPlace>
      goals;  ///< in the order they are driven to; the last lies past the stairs
  std::vector<FloorOpening> openings;
  double door_gap = 0.0;  ///< [m] the free width the door leaf leaves in its frame
};

/// The widest door gap [m]: the door's 1.0 m leaf opened to 90 degrees, less half its 4 cm
/// thickness.
constexpr double kOfficeDoorMaxGap = 0.98;

/// Builds the office. `seed` moves the chairs (people leave them where they stood up: up to
/// 0.15 m and 30 degrees from their places at the desks) and phases the walkers. `door_gap`
/// [m] is the free width the door leaf leaves (clamped to (0.05, kOfficeDoorMaxGap]).
OfficeGoalsLayout make_office_goals_scene(std::uint64_t seed, double door_gap);

}  // namespace rigdesign::sim
