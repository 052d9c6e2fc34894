// The walking person of paper 3's cell and of the office_goals scenario's passers-by.
#include "rigdesign/sim/mesh_primitives.hpp"
#include "rigdesign/sim/person_links.hpp"
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

// [m] how far each link volume reaches past its part of the mesh: one sigma of the cell's
// noisiest sensors (3 cm range noise), so a noisy point on the body stays inside as a rule.
constexpr double kVolumeMargin = 0.03;
// [m] paper 3's own example radius (shoulder to elbow); it holds our 0.14 m legs (half
// diagonal 0.099 m) and 0.08 m arms.
constexpr double kLimbRadius = 0.1;

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

std::vector<BodyLink> person_links() {
  using model::Vec3;
  const double leg_y = kLegSpacing / 2;
  const double arm_y = kTorsoWidth / 2 + kArmSide / 2;
  const double elbow = (kTorsoTop + kArmBottom) / 2;
  const double m = kVolumeMargin;
  std::vector<BodyLink> links;
  for (const double side : {1.0, -1.0}) {
    const std::string name = side > 0 ? "left " : "right ";
    links.push_back({name + "leg", Vec3(0, side * leg_y, kLegTop), Vec3(0, side * leg_y, 0),
                     LinkShape::cylinder, kLimbRadius, 0, 0});
    links.push_back({name + "upper arm", Vec3(0, side * arm_y, kTorsoTop),
                     Vec3(0, side * arm_y, elbow), LinkShape::cylinder, kLimbRadius, 0, 0});
    links.push_back({name + "forearm", Vec3(0, side * arm_y, elbow),
                     Vec3(0, side * arm_y, kArmBottom - m), LinkShape::cylinder, kLimbRadius, 0,
                     0});
  }
  // The torso's volume reaches past its bottom face so that face lies inside it, not on its
  // end cap, where rounding decides.
  links.push_back({"torso", Vec3(0, 0, kTorsoTop + m), Vec3(0, 0, kLegTop - m), LinkShape::prism, 0,
                   kTorsoWidth + 2 * m, kTorsoDepth + 2 * m});
  links.push_back({"head", Vec3(0, 0, kTorsoTop), Vec3(0, 0, kBodyHeight + m), LinkShape::cylinder,
                   kHeadRadius + m, 0, 0});
  return links;
}

}  // namespace rigdesign::sim
