// The corridor: 15 m long, 2 m wide, 2.5 m high, closed at both ends, with a door recess in
// each side wall and one box on the floor. The robot stands at the start facing along +x.
#include <algorithm>
#include <string>

#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

// Corridor [m]: floor x in [0, 15], y in [-1, 1].
constexpr double kLength = 15.0;
constexpr double kHalfWidth = 1.0;
constexpr double kCorridorWallHeight = 2.5;
// Side walls are solid masonry, 25 cm thick; a door sits 20 cm back in it, leaving a recess.
constexpr double kWallThickness = 0.25;
constexpr double kRecessDepth = 0.2;
constexpr double kEndWallThickness = 0.1;

// Doors [m]: a standard 0.9 x 2.1 m interior door leaf, 5 cm thick.
constexpr double kDoorWidth = 0.9;
constexpr double kDoorHeight = 2.1;
constexpr double kDoorLeftX = 5.0;    // start of the door in the left (+y) wall
constexpr double kDoorRightX = 10.0;  // start of the door in the right (-y) wall

// A 40 x 30 x 30 cm box on the floor, right of the centre line, 7 m ahead of the robot.
const model::Vec3 kBoxSize(0.4, 0.3, 0.3);
constexpr double kBoxX = 8.0;
constexpr double kBoxY = -0.5;

constexpr double kRobotX = 1.0;  // [m] from the start wall

// One side wall with a door recess starting at `door_x`; `side` is +1 (left) or -1 (right).
void add_side_wall(model::Scene& scene, const std::string& name, double side, double door_x) {
  const double inner = side * kHalfWidth;
  const double outer = side * (kHalfWidth + kWallThickness);
  const double door_back = side * (kHalfWidth + kRecessDepth);
  auto span = [&](double x0, double x1, double y0, double y1, double z0, double z1) {
    return aligned_box({x0, std::min(y0, y1), z0}, {x1, std::max(y0, y1), z1});
  };
  const double door_end = door_x + kDoorWidth;
  add_object(scene, name + "_1", span(0, door_x, inner, outer, 0, kCorridorWallHeight));
  add_object(scene, name + "_2", span(door_end, kLength, inner, outer, 0, kCorridorWallHeight));
  add_object(scene, name + "_lintel",
             span(door_x, door_end, inner, outer, kDoorHeight, kCorridorWallHeight));
  add_object(scene, name + "_door", span(door_x, door_end, door_back, outer, 0, kDoorHeight));
}

}  // namespace

model::Scene make_corridor_scene() {
  model::Scene scene;
  scene.name = "corridor";
  scene.T_world_robot = floor_pose(kRobotX, 0, 0);

  model::TriangleMesh floor = floor_rectangle({{0, -kHalfWidth}, {kLength, kHalfWidth}}, 0);
  // The recesses' floors, in front of each door.
  floor.append(floor_rectangle(
      {{kDoorLeftX, kHalfWidth}, {kDoorLeftX + kDoorWidth, kHalfWidth + kRecessDepth}}, 0));
  floor.append(floor_rectangle(
      {{kDoorRightX, -kHalfWidth - kRecessDepth}, {kDoorRightX + kDoorWidth, -kHalfWidth}}, 0));
  add_object(scene, "floor", std::move(floor));

  const double outer_y = kHalfWidth + kWallThickness;
  add_object(scene, "wall_start",
             aligned_box({-kEndWallThickness, -outer_y, 0}, {0, outer_y, kCorridorWallHeight}));
  add_object(scene, "wall_end",
             aligned_box({kLength, -outer_y, 0},
                         {kLength + kEndWallThickness, outer_y, kCorridorWallHeight}));
  add_side_wall(scene, "wall_left", +1, kDoorLeftX);
  add_side_wall(scene, "wall_right", -1, kDoorRightX);

  add_object(
      scene, "box",
      box_mesh(kBoxSize, model::Pose3(Eigen::Translation3d(kBoxX, kBoxY, kBoxSize.z() / 2))));
  return scene;
}

}  // namespace rigdesign::sim
