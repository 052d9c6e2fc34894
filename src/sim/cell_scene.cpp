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

// Body [m], a 1.75 m adult about 0.5 m across the arms (shoulder breadth ~0.45 m plus arms);
// every part is centred on the body's vertical axis in x and symmetric in y, so the mesh's
// vertex centroid lies on that axis.
constexpr double kLegTop = 0.85;
constexpr double kLegSide = 0.14;
constexpr double kLegSpacing = 0.2;  // between the legs' centres
constexpr double kTorsoTop = 1.45;
constexpr double kTorsoDepth = 0.24;
constexpr double kTorsoWidth = 0.34;
constexpr double kArmSide = 0.08;
constexpr double kArmBottom = 0.8;
constexpr double kNeckRadius = 0.05;
constexpr double kHeadBottom = 1.5;
constexpr double kHeadRadius = 0.1;
constexpr double kBodyHeight = 1.75;

model::TriangleMesh person_mesh() {
  model::TriangleMesh body;
  auto part = [&](double half_x, double y0, double y1, double z0, double z1) {
    body.append(aligned_box({-half_x, y0, z0}, {half_x, y1, z1}));
  };
  const double leg_half = kLegSide / 2;
  part(leg_half, kLegSpacing / 2 - leg_half, kLegSpacing / 2 + leg_half, 0, kLegTop);
  part(leg_half, -kLegSpacing / 2 - leg_half, -kLegSpacing / 2 + leg_half, 0, kLegTop);
  part(kTorsoDepth / 2, -kTorsoWidth / 2, kTorsoWidth / 2, kLegTop, kTorsoTop);
  const double arm_half = kArmSide / 2;
  part(arm_half, kTorsoWidth / 2, kTorsoWidth / 2 + kArmSide, kArmBottom, kTorsoTop);
  part(arm_half, -kTorsoWidth / 2 - kArmSide, -kTorsoWidth / 2, kArmBottom, kTorsoTop);
  body.append(cylinder_mesh(kNeckRadius, kHeadBottom - kTorsoTop,
                            model::Pose3(Eigen::Translation3d(0, 0, kTorsoTop))));
  body.append(cylinder_mesh(kHeadRadius, kBodyHeight - kHeadBottom,
                            model::Pose3(Eigen::Translation3d(0, 0, kHeadBottom))));
  return body;
}

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
  scene.moving.push_back({"person", person_mesh(), T_world_person});
  return scene;
}

}  // namespace rigdesign::sim
