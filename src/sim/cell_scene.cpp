// Paper 3's collaborative cell: a 4 x 4 m cell centred on the world origin (the cell frame
// is the world frame), a 0.8 x 0.6 x 1 m plate in its centre, and a person walking an
// ellipse with semi-axes 2 m (x) and 1 m (y) around it, twice in 96 s. The cell's sensors
// are fixed; the robot frame they hang from stands at the centre of the -y side, facing in.
#include <cmath>
#include <numbers>

#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

// Floor [m]: the 4 m cell plus a 1 m margin, since the person's body reaches past the cell's
// edge at the ellipse's ends (x = +-2 m).
constexpr double kCellHalfSide = 2.0;
constexpr double kFloorMargin = 1.0;

// Plate [m], paper 3.
const model::Vec3 kPlateSize(0.8, 0.6, 1.0);

// Walk, paper 3: semi-axes [m], two laps in about 96 s, so one lap in 48 s [s].
constexpr double kSemiAxisX = 2.0;
constexpr double kSemiAxisY = 1.0;
constexpr double kLapPeriod = 48.0;

// On the ellipse at angle 2 pi t / period, counter-clockwise from (a, 0), facing along the
// tangent (the way the person walks).
model::Pose3 T_world_person(double t) {
  const double angle = 2 * std::numbers::pi * t / kLapPeriod;
  const double x = kSemiAxisX * std::cos(angle);
  const double y = kSemiAxisY * std::sin(angle);
  const double heading = std::atan2(kSemiAxisY * std::cos(angle), -kSemiAxisX * std::sin(angle));
  return floor_pose(x, y, heading);
}

}  // namespace

model::Scene make_cell_scene() {
  model::Scene scene;
  scene.name = "cell";
  scene.T_world_robot = floor_pose(0, -kCellHalfSide, std::numbers::pi / 2);
  const double half = kCellHalfSide + kFloorMargin;
  add_object(scene, "floor", floor_rectangle({{-half, -half}, {half, half}}, 0));
  add_object(scene, "plate",
             box_mesh(kPlateSize, model::Pose3(Eigen::Translation3d(0, 0, kPlateSize.z() / 2))));
  scene.moving.push_back({"person", person_mesh(), T_world_person, 0.0});
  return scene;
}

}  // namespace rigdesign::sim
