// The office_goals scenario's office (issue 35 item 2; paper 2's office with people moving
// chairs and doors). A 9 x 6 m room with three desks along each long wall and a chair at each,
// a 2.9 m side room behind a door left ajar, a landing on the left whose stairwell goes down
// 1 m across its whole width, and two people walking across the room. World frame: the main
// room's floor spans x 0..9, y 0..6 m; the robot starts at (1, 3) facing +x.
#include "rigdesign/sim/office_goals_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "office_furniture.hpp"
#include "rigdesign/sim/noise_stream.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
// A namespace of its own: the unity build joins this file with the stairs and office scenes,
// whose unnamed namespaces use the same names (kRisers, add_stairwell).
namespace office_goals_parts {
namespace {

// Walls [m]: 0.1 m thick, 1.2 m high (above every sensor of a small indoor robot).
constexpr double kWall = 0.1;
constexpr double kWallHeight = 1.2;
constexpr double kRoomLength = 9.0;  // main room, x 0..9
constexpr double kRoomWidth = 6.0;   // y 0..6
constexpr double kSideRoomEnd = 12.0;
// Door [m]: in the inner wall at x 9.0..9.1, frame y 2.5..3.5, hinged at its -y jamb, opening
// into the side room.
constexpr double kDoorLow = 2.5;
constexpr double kDoorHigh = 3.5;
constexpr double kLeaf = 1.0;
constexpr double kLeafThickness = 0.04;
// Landing [m]: an opening in the left wall, y 2..4, to a landing x -3..0 whose stairwell
// (x -2.0..-0.4) spans its width: the far end (x -3..-2) can only be reached across it.
constexpr double kLandingLow = 2.0;
constexpr double kLandingHigh = 4.0;
constexpr double kLandingEnd = -3.0;
constexpr double kStairsTop = -0.4;   // the upper floor's edge the flight drops from
constexpr double kStairsFoot = -2.0;  // the far edge of the well
// Flight: 6 risers of 1/6 m and 27 cm treads going down towards -x (building codes' usual
// 15-18 cm risers and >= 25 cm treads); the 6th riser lands on the lower floor at z = -1.
constexpr int kRisers = 6;
constexpr double kTread = 0.27;
constexpr double kLowerFloorZ = -1.0;

// Desks [m]: x centres of the three desks in each row, each against its wall.
constexpr double kDeskX[3] = {1.6, 3.6, 5.6};
// Chair columns [m] from the desk's wall-side edge: the seat's front under the desk's edge.
constexpr double kChairFromDeskEdge = 0.25;
// Seeded disorder: chairs left up to 0.15 m further out and to either side, turned up to 30 deg.
constexpr double kChairShift = 0.15;
constexpr double kChairTurn = std::numbers::pi / 6;

// Walkers [m, m/s, s]: back and forth across the room between y 2.1 and 3.9 at x 2.6 and 6.8
// (clear of the chairs), at 0.6 m/s (an unhurried indoor pace), pausing 2 s at each end.
constexpr double kWalkLow = 2.1;
constexpr double kWalkHigh = 3.9;
constexpr double kWalkerX[2] = {2.6, 6.8};
constexpr double kWalkSpeed = 0.6;
constexpr double kWalkPause = 2.0;
// [m] a walker stops while a robot's centre is this close: a 0.45 m robot's edge 0.5 m from
// the person's 0.25 m half-width (the personal space people keep from a machine).
constexpr double kGiveWayWithin = 1.2;

// Stream ids of the layout's draws, away from the other seeded streams.
constexpr std::uint64_t kChairStream = 3u << 20;
constexpr std::uint64_t kWalkerStream = (3u << 20) + 1;

void add_box(model::Scene& scene, const std::string& name, const model::Vec3& low,
             const model::Vec3& high) {
  add_object(scene, name, aligned_box(low, high));
}

void add_walls(model::Scene& scene) {
  const double h = kWallHeight;
  add_box(scene, "wall_south", {kLandingEnd - kWall, -kWall, 0}, {kSideRoomEnd + kWall, 0, h});
  add_box(scene, "wall_north", {kLandingEnd - kWall, kRoomWidth, 0},
          {kSideRoomEnd + kWall, kRoomWidth + kWall, h});
  add_box(scene, "wall_east", {kSideRoomEnd, 0, 0}, {kSideRoomEnd + kWall, kRoomWidth, h});
  add_box(scene, "wall_west_1", {-kWall, 0, 0}, {0, kLandingLow, h});
  add_box(scene, "wall_west_2", {-kWall, kLandingHigh, 0}, {0, kRoomWidth, h});
  add_box(scene, "inner_wall_1", {kRoomLength, 0, 0}, {kRoomLength + kWall, kDoorLow, h});
  add_box(scene, "inner_wall_2", {kRoomLength, kDoorHigh, 0}, {kRoomLength + kWall, kRoomWidth, h});
  add_box(scene, "landing_wall_south", {kLandingEnd, kLandingLow - kWall, kLowerFloorZ},
          {-kWall, kLandingLow, h});
  add_box(scene, "landing_wall_north", {kLandingEnd, kLandingHigh, kLowerFloorZ},
          {-kWall, kLandingHigh + kWall, h});
  add_box(scene, "landing_wall_end", {kLandingEnd - kWall, kLandingLow, 0},
          {kLandingEnd, kLandingHigh, h});
}

// The stairwell: steps as solid blocks from the lower floor up to their treads, the lower
// floor, and walls below the floor at both edges so every ray into the well ends on a surface.
void add_stairwell(model::Scene& scene) {
  const double rise = -kLowerFloorZ / kRisers;
  for (int step = 1; step < kRisers; ++step) {
    add_box(scene, "stairs_step_" + std::to_string(step),
            {kStairsTop - step * kTread, kLandingLow, kLowerFloorZ},
            {kStairsTop - (step - 1) * kTread, kLandingHigh, -step * rise});
  }
  add_object(scene, "stairs_lower_floor",
             floor_rectangle(
                 {{kStairsFoot, kLandingLow}, {kStairsTop - (kRisers - 1) * kTread, kLandingHigh}},
                 kLowerFloorZ));
  add_box(scene, "stairwell_edge", {kStairsTop, kLandingLow, kLowerFloorZ},
          {kStairsTop + kWall, kLandingHigh, 0});
  add_box(scene, "stairwell_far_wall", {kStairsFoot - kWall, kLandingLow, kLowerFloorZ},
          {kStairsFoot, kLandingHigh, 0});
}

// The leaf's opening angle [rad] that leaves `gap` [m] between its free edge and the far
// jamb: gap = L (1 - cos a) - t sin a / 2 grows with a, solved by bisection.
double leaf_angle(double gap) {
  double low = 0.0;
  double high = std::numbers::pi / 2;
  for (int i = 0; i < 60; ++i) {
    const double a = 0.5 * (low + high);
    const double free = kLeaf * (1 - std::cos(a)) - 0.5 * kLeafThickness * std::sin(a);
    (free < gap ? low : high) = a;
  }
  return 0.5 * (low + high);
}

void add_door(model::Scene& scene, double gap) {
  const double a = leaf_angle(gap);
  // Closed, the leaf runs +y from the hinge; opened by a it points along (sin a, cos a).
  const model::Vec2 hinge(kRoomLength + kWall, kDoorLow);
  const model::Vec2 along(std::sin(a), std::cos(a));
  const model::Vec2 centre = hinge + 0.5 * kLeaf * along;
  model::Pose3 T_world_leaf = floor_pose(centre.x(), centre.y(), -a);
  T_world_leaf.translate(model::Vec3(0, 0, kWallHeight / 2));
  add_object(scene, "door", box_mesh({kLeafThickness, kLeaf, kWallHeight}, T_world_leaf));
}

void add_desks(model::Scene& scene, std::mt19937_64& chairs) {
  std::uniform_real_distribution<double> shift(-kChairShift, kChairShift);
  std::uniform_real_distribution<double> out(0.0, kChairShift);
  std::uniform_real_distribution<double> turn(-kChairTurn, kChairTurn);
  for (int row = 0; row < 2; ++row) {
    const bool north = row == 0;
    // Desk against its wall (2 cm off it); chair in front of it, facing it.
    const double desk_y = north ? kRoomWidth - 0.02 - kTableDepth / 2 : 0.02 + kTableDepth / 2;
    const double edge_y = north ? desk_y - kTableDepth / 2 : desk_y + kTableDepth / 2;
    const double towards_room = north ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i) {
      const std::string id = std::string(north ? "north" : "south") + "_" + std::to_string(i + 1);
      add_office_table(scene, "desk_" + id, floor_pose(kDeskX[i], desk_y, 0));
      const double x = kDeskX[i] + shift(chairs);
      const double y = edge_y + towards_room * (kChairFromDeskEdge + out(chairs));
      const double facing = (north ? std::numbers::pi / 2 : -std::numbers::pi / 2) + turn(chairs);
      add_office_chair(scene, "chair_" + id, floor_pose(x, y, facing));
    }
  }
  // The side room's desk along its far wall, its chair pushed in.
  add_office_table(scene, "desk_side",
                   floor_pose(kSideRoomEnd - 0.02 - kTableDepth / 2, 1.2, std::numbers::pi / 2));
}

// Back and forth between y low and high at x, from `phase` [s] into the cycle.
model::Pose3 walker_pose(double x, double phase, double t) {
  const double leg = (kWalkHigh - kWalkLow) / kWalkSpeed;
  const double cycle = 2 * (leg + kWalkPause);
  const double s = std::fmod(t + phase, cycle);
  if (s < leg) return floor_pose(x, kWalkLow + kWalkSpeed * s, std::numbers::pi / 2);
  if (s < leg + kWalkPause) return floor_pose(x, kWalkHigh, std::numbers::pi / 2);
  if (s < 2 * leg + kWalkPause) {
    return floor_pose(x, kWalkHigh - kWalkSpeed * (s - leg - kWalkPause), -std::numbers::pi / 2);
  }
  return floor_pose(x, kWalkLow, -std::numbers::pi / 2);
}

void add_walkers(model::Scene& scene, std::mt19937_64& walkers) {
  const double cycle = 2 * ((kWalkHigh - kWalkLow) / kWalkSpeed + kWalkPause);
  std::uniform_real_distribution<double> phase(0.0, cycle);
  for (int i = 0; i < 2; ++i) {
    const double x = kWalkerX[i];
    const double p = phase(walkers);
    scene.moving.push_back({"person_" + std::to_string(i + 1), person_mesh(),
                            [x, p](double t) { return walker_pose(x, p, t); }, kGiveWayWithin});
  }
}

}  // namespace

OfficeGoalsLayout build(std::uint64_t seed, double door_gap) {
  OfficeGoalsLayout layout;
  layout.door_gap = std::clamp(door_gap, 0.05, kOfficeDoorMaxGap);
  model::Scene& scene = layout.scene;
  scene.name = "office_goals";
  scene.T_world_robot = floor_pose(1.0, 3.0, 0.0);
  const Rect2 well{{kStairsFoot, kLandingLow}, {kStairsTop, kLandingHigh}};
  add_object(scene, "floor",
             floor_with_openings({{kLandingEnd, 0}, {kSideRoomEnd, kRoomWidth}}, {well}, 0));
  add_walls(scene);
  add_stairwell(scene);
  add_door(scene, layout.door_gap);
  std::mt19937_64 chairs = noise_stream(seed, kChairStream);
  add_desks(scene, chairs);
  std::mt19937_64 walkers = noise_stream(seed, kWalkerStream);
  add_walkers(scene, walkers);
  layout.openings.push_back({"stairwell", well});
  // Through the door on the line halfway across its gap.
  const double door_y = kDoorHigh - 0.5 * layout.door_gap;
  layout.goals = {{"between the north chairs", {4.6, 4.3}},
                  {"before the door", {8.4, door_y}},
                  {"side room, through the door ajar", {10.6, door_y}},
                  {"printer corner", {7.6, 1.3}},
                  {"between the south chairs", {2.6, 1.65}},
                  {"head of the stairs", {0.6, 3.0}},
                  {"landing past the stairwell", {-2.5, 3.0}}};
  return layout;
}

}  // namespace office_goals_parts

OfficeGoalsLayout make_office_goals_scene(std::uint64_t seed, double door_gap) {
  return office_goals_parts::build(seed, door_gap);
}

}  // namespace rigdesign::sim
