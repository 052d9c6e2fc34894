// Stairs: negative obstacles (paper 2). A floor at z = 0 with a 1.2 m wide stairwell whose
// flight goes down 1 m to a lower floor, and elsewhere a 0.4 x 0.4 m hole over a 0.5 m pit.
// The floor is built around both openings, so nothing at z = 0 covers them; walls below the
// floor line the stairwell and the pit so rays into them end on a surface.
#include <string>
#include <vector>

#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

// Floor [m] around the robot, which stands at the origin facing +x.
const Rect2 kFloor{{-2.0, -3.0}, {7.0, 3.0}};

// Stairwell [m]: opening x in [2, 4.5] (2 m ahead of the robot), y in [-0.6, 0.6].
constexpr double kStairwellStartX = 2.0;
constexpr double kStairwellLength = 2.5;
constexpr double kStairwellHalfWidth = 0.6;
// Flight: one storey step of 1 m in 6 risers of 1/6 m (within building codes' usual
// 15-18 cm) and 28 cm treads (the common code minimum); the 6th riser lands on the lower floor.
constexpr double kStairsLowerFloorZ = -1.0;
constexpr int kStairsRisers = 6;
constexpr double kStairsTread = 0.28;
// Walls below the floor line the stairwell and the pit [m].
constexpr double kStairwellWallThickness = 0.1;

// Pit [m]: a 0.4 x 0.4 m hole, 0.5 m deep, ahead-left of the robot, clear of the stairwell.
const Rect2 kPit{{1.0, 1.0}, {1.4, 1.4}};
constexpr double kPitDepth = 0.5;
constexpr double kPitWallThickness = 0.05;

void add_stairs_stairwell(model::Scene& scene) {
  const double x0 = kStairwellStartX;
  const double x1 = kStairwellStartX + kStairwellLength;
  const double y = kStairwellHalfWidth;
  const double t = kStairwellWallThickness;
  const double rise = -kStairsLowerFloorZ / kStairsRisers;
  // Each step is a solid block from the lower floor up to its tread.
  for (int step = 1; step < kStairsRisers; ++step) {
    add_object(scene, "step_" + std::to_string(step),
               aligned_box({x0 + (step - 1) * kStairsTread, -y, kStairsLowerFloorZ},
                           {x0 + step * kStairsTread, y, -step * rise}));
  }
  const double flight_end = x0 + (kStairsRisers - 1) * kStairsTread;
  add_object(scene, "lower_floor",
             floor_rectangle({{flight_end, -y}, {x1, y}}, kStairsLowerFloorZ));
  // The start wall is the upper floor's edge, which the first riser drops from.
  add_object(scene, "stairwell_wall_start",
             aligned_box({x0 - t, -y - t, kStairsLowerFloorZ}, {x0, y + t, 0}));
  add_object(scene, "stairwell_wall_end",
             aligned_box({x1, -y - t, kStairsLowerFloorZ}, {x1 + t, y + t, 0}));
  add_object(scene, "stairwell_wall_left",
             aligned_box({x0, y, kStairsLowerFloorZ}, {x1, y + t, 0}));
  add_object(scene, "stairwell_wall_right",
             aligned_box({x0, -y - t, kStairsLowerFloorZ}, {x1, -y, 0}));
}

void add_pit(model::Scene& scene) {
  const model::Vec2& low = kPit.low;
  const model::Vec2& high = kPit.high;
  const double t = kPitWallThickness;
  const double bottom = -kPitDepth;
  add_object(
      scene, "pit_bottom",
      aligned_box({low.x() - t, low.y() - t, bottom - t}, {high.x() + t, high.y() + t, bottom}));
  add_object(scene, "pit_wall_1",
             aligned_box({low.x() - t, low.y() - t, bottom}, {low.x(), high.y() + t, 0}));
  add_object(scene, "pit_wall_2",
             aligned_box({high.x(), low.y() - t, bottom}, {high.x() + t, high.y() + t, 0}));
  add_object(scene, "pit_wall_3",
             aligned_box({low.x(), low.y() - t, bottom}, {high.x(), low.y(), 0}));
  add_object(scene, "pit_wall_4",
             aligned_box({low.x(), high.y(), bottom}, {high.x(), high.y() + t, 0}));
}

}  // namespace

model::Scene make_stairs_scene() {
  model::Scene scene;
  scene.name = "stairs";
  scene.T_world_robot = floor_pose(0, 0, 0);
  const Rect2 stairwell{{kStairwellStartX, -kStairwellHalfWidth},
                        {kStairwellStartX + kStairwellLength, kStairwellHalfWidth}};
  add_object(scene, "floor", floor_with_openings(kFloor, {stairwell, kPit}, 0));
  add_stairs_stairwell(scene);
  add_pit(scene);
  return scene;
}

}  // namespace rigdesign::sim
