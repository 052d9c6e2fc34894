#pragma once
// Office tables and chairs built from named parts, every part a closed solid. Each piece is
// placed by a pose on the floor; its own frame has z up from the floor. Private to sim.
#include <string>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/scene.hpp"

namespace rigdesign::sim {

/// Table top [m]: the 1.4 x 0.7 m desk of the brief, 0.74 m high (EN 527-1's fixed desk height).
constexpr double kTableLength = 1.4;  // along the table's x
constexpr double kTableDepth = 0.7;   // along the table's y
constexpr double kTableHeight = 0.74;

/// How far [m] the hanging cable's floor end lies beyond the table's -y edge.
constexpr double kCableReach = 0.12;

/// Radius [m] around the chair's column that all of its parts stay within (the backrest's
/// outer corners are the farthest).
constexpr double kChairReach = 0.36;

/// Adds "<name>_top" and "<name>_leg_1" .. "<name>_leg_4". `T_world_table`: origin on the
/// floor below the top's centre, x along the long side.
void add_office_table(model::Scene& scene, const std::string& name,
                      const model::Pose3& T_world_table);

/// Adds "<name>_seat", "<name>_back", "<name>_column", the star base's thin radial bars
/// "<name>_leg_1" .. "<name>_leg_5" and "<name>_casters". `T_world_chair`: origin on the floor
/// below the column, x the way the sitter faces.
void add_office_chair(model::Scene& scene, const std::string& name,
                      const model::Pose3& T_world_chair);

/// Adds "cable": a 1 cm cord hanging from the -y long edge of the table at `T_world_table`
/// down to the floor kCableReach beyond that edge.
void add_hanging_cable(model::Scene& scene, const model::Pose3& T_world_table);

}  // namespace rigdesign::sim
