#include "office_furniture.hpp"

#include <cmath>
#include <numbers>

#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

// Table [m]: a 3 cm board on 4 cm square legs set 5 cm in from its edges.
constexpr double kTopThickness = 0.03;
constexpr double kTableLegSide = 0.04;
constexpr double kTableLegInset = 0.05;

// Chair [m], after EN 1335-1 (seat height adjustable 0.42-0.51 m, five-star base) and a
// typical task chair: base diameter about 0.6 m on 5 cm casters.
constexpr double kSeatTop = 0.45;
constexpr double kSeatThickness = 0.06;
constexpr double kSeatDepth = 0.46;  // along the chair's x
constexpr double kSeatWidth = 0.48;
constexpr double kBackWidth = 0.44;
constexpr double kBackThickness = 0.05;
constexpr double kBackBottom = 0.55;
constexpr double kBackTop = 1.0;
constexpr double kBackStrutSide = 0.04;  // the bar joining seat and backrest
constexpr double kColumnRadius = 0.025;  // the gas spring's tube
constexpr double kHubRadius = 0.04;
constexpr int kStarLegs = 5;
// The star base's bars are as thin as the brief's 2 cm: thin enough for a sparse lidar's
// rays to pass either side of them, which is what the scene is meant to test.
constexpr double kStarLegSide = 0.02;
constexpr double kStarLegInner = 0.03;  // bar start, inside the hub
constexpr double kStarLegOuter = 0.30;  // bar end, above the caster's axle
constexpr double kCasterRadius = 0.025;
constexpr double kCasterHeight = 0.05;  // the bars rest on the casters

// Cable [m]: a 1 cm cord, e.g. a laptop's power lead, hanging 0.3 m from the table's centre.
constexpr double kCableRadius = 0.005;
constexpr double kCableAlongTable = 0.3;

model::Pose3 translated(const model::Pose3& T_world_frame, const model::Vec3& offset) {
  model::Pose3 T_world_part = T_world_frame;
  T_world_part.translate(offset);
  return T_world_part;
}

}  // namespace

void add_office_table(model::Scene& scene, const std::string& name,
                      const model::Pose3& T_world_table) {
  add_object(scene, name + "_top",
             box_mesh({kTableLength, kTableDepth, kTopThickness},
                      translated(T_world_table, {0, 0, kTableHeight - kTopThickness / 2})));
  const double leg_height = kTableHeight - kTopThickness;
  const double leg_x = kTableLength / 2 - kTableLegInset - kTableLegSide / 2;
  const double leg_y = kTableDepth / 2 - kTableLegInset - kTableLegSide / 2;
  const double corners[4][2] = {{leg_x, leg_y}, {-leg_x, leg_y}, {-leg_x, -leg_y}, {leg_x, -leg_y}};
  for (int leg = 0; leg < 4; ++leg) {
    add_object(
        scene, name + "_leg_" + std::to_string(leg + 1),
        box_mesh({kTableLegSide, kTableLegSide, leg_height},
                 translated(T_world_table, {corners[leg][0], corners[leg][1], leg_height / 2})));
  }
}

void add_office_chair(model::Scene& scene, const std::string& name,
                      const model::Pose3& T_world_chair) {
  const double seat_bottom = kSeatTop - kSeatThickness;
  add_object(scene, name + "_seat",
             box_mesh({kSeatDepth, kSeatWidth, kSeatThickness},
                      translated(T_world_chair, {0, 0, kSeatTop - kSeatThickness / 2})));

  const double back_x = -(kSeatDepth / 2 + kBackThickness / 2);
  model::TriangleMesh back =
      box_mesh({kBackThickness, kBackWidth, kBackTop - kBackBottom},
               translated(T_world_chair, {back_x, 0, (kBackBottom + kBackTop) / 2}));
  back.append(box_mesh({kBackStrutSide, kBackStrutSide, kBackBottom - kSeatTop},
                       translated(T_world_chair, {back_x, 0, (kSeatTop + kBackBottom) / 2})));
  add_object(scene, name + "_back", std::move(back));

  const double bar_bottom = kCasterHeight;
  const double bar_top = bar_bottom + kStarLegSide;
  model::TriangleMesh column = cylinder_mesh(kHubRadius, bar_top - bar_bottom,
                                             translated(T_world_chair, {0, 0, bar_bottom}));
  column.append(cylinder_mesh(kColumnRadius, seat_bottom - bar_top,
                              translated(T_world_chair, {0, 0, bar_top})));
  add_object(scene, name + "_column", std::move(column));

  model::TriangleMesh casters;
  const double bar_length = kStarLegOuter - kStarLegInner;
  for (int leg = 0; leg < kStarLegs; ++leg) {
    const double angle = 2 * std::numbers::pi * leg / kStarLegs;
    model::Pose3 T_world_bar = T_world_chair;
    T_world_bar.rotate(Eigen::AngleAxisd(angle, model::Vec3::UnitZ()));
    add_object(scene, name + "_leg_" + std::to_string(leg + 1),
               box_mesh({bar_length, kStarLegSide, kStarLegSide},
                        translated(T_world_bar, {(kStarLegInner + kStarLegOuter) / 2, 0,
                                                 (bar_bottom + bar_top) / 2})));
    casters.append(cylinder_mesh(kCasterRadius, kCasterHeight,
                                 translated(T_world_bar, {kStarLegOuter, 0, 0})));
  }
  add_object(scene, name + "_casters", std::move(casters));
}

void add_hanging_cable(model::Scene& scene, const model::Pose3& T_world_table) {
  // From just outside the top's edge, level with the board's middle, down to rest on the floor.
  const model::Vec3 edge_table(kCableAlongTable, -(kTableDepth / 2 + kCableRadius),
                               kTableHeight - kTopThickness / 2);
  const model::Vec3 floor_table(kCableAlongTable, -(kTableDepth / 2 + kCableReach), kCableRadius);
  add_object(
      scene, "cable",
      cylinder_between(T_world_table * edge_table, T_world_table * floor_table, kCableRadius));
}

}  // namespace rigdesign::sim
