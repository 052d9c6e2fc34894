// The walking person of paper 3's cell and of the office_goals scenario's passers-by.
#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

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

}  // namespace

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

}  // namespace rigdesign::sim
