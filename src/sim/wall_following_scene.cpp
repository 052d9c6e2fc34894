// Wall following (paper 1, Fig. 11): the robot drives along +x with a wall on its left, past
// a low table standing against the wall. The table's top is a foam slab that overhangs its
// legs towards the robot's path, below the view of a lidar mounted at about 1 m: the legs
// stand clear of the path, the foam reaches into it.
#include <string>

#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

// Wall [m]: its face 0.6 m left of the robot's path (y = 0), 2.5 m high, from 2 m behind
// the robot's start to 12 m ahead of it.
constexpr double kWallY = 0.6;
constexpr double kFollowedWallThickness = 0.1;
constexpr double kFollowedWallHeight = 2.5;
constexpr double kSceneStartX = -2.0;
constexpr double kSceneEndX = 12.0;
constexpr double kFloorRightY = -2.0;  // floor reaches 2 m right of the path

// Table [m]: 1.2 m long, 3 m ahead of the robot's start, against the wall; its 4 cm legs
// span 0.3 m out from the wall, so they stand 0.3 m left of the path's centre line.
constexpr double kTableStartX = 3.0;
constexpr double kTableLength = 1.2;
constexpr double kLegFrameDepth = 0.3;
constexpr double kFoamTableLegSide = 0.04;
// Foam top [m]: 0.39 m high overall, 6 cm thick, overhanging the legs by 15 cm on the path
// side only, so its edge is 0.15 m left of the path's centre line. Close up only the UR
// Cleaner's front camera sees the slab (paper 1, Fig. 11): its top at 0.39 m passes under the
// VLP-16's lowest beam (-15 deg from 1.04 m) within 2.4 m of the lidar, so the lidar meets
// only its edge, briefly, from farther away; its bottom at 0.33 m stays above the left pico
// flexx's view.
constexpr double kTableHeight = 0.39;
constexpr double kFoamThickness = 0.06;
constexpr double kFoamOverhang = 0.15;

void add_table(model::Scene& scene) {
  const double x0 = kTableStartX;
  const double x1 = kTableStartX + kTableLength;
  const double legs_y = kWallY - kLegFrameDepth;
  const double foam_bottom = kTableHeight - kFoamThickness;
  add_object(scene, "foam",
             aligned_box({x0, legs_y - kFoamOverhang, foam_bottom}, {x1, kWallY, kTableHeight}));
  const double leg_x[2] = {x0, x1 - kFoamTableLegSide};
  const double leg_y[2] = {legs_y, kWallY - kFoamTableLegSide};
  int leg = 0;
  for (double x : leg_x) {
    for (double y : leg_y) {
      add_object(
          scene, "table_leg_" + std::to_string(++leg),
          aligned_box({x, y, 0}, {x + kFoamTableLegSide, y + kFoamTableLegSide, foam_bottom}));
    }
  }
}

}  // namespace

model::Scene make_wall_following_scene() {
  model::Scene scene;
  scene.name = "wall_following";
  scene.T_world_robot = floor_pose(0, 0, 0);
  add_object(scene, "floor",
             floor_rectangle({{kSceneStartX, kFloorRightY}, {kSceneEndX, kWallY}}, 0));
  add_object(scene, "wall",
             aligned_box({kSceneStartX, kWallY, 0},
                         {kSceneEndX, kWallY + kFollowedWallThickness, kFollowedWallHeight}));
  add_table(scene);
  return scene;
}

}  // namespace rigdesign::sim
