// The office: an 8 x 6 m room, 2.6 m high, furnished at random for a seed. Furniture goes
// into a 3 x 3 grid of 1.8 m slots, one piece per slot, turned and shifted at random within
// its slot, so pieces never overlap and the aisle in front of the robot stays free.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "office_furniture.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/sim/mesh_primitives.hpp"
#include "scene_generators.hpp"

namespace rigdesign::sim {
namespace {

// Room [m]: floor x in [0, 8], y in [-3, 3]; walls are 10 cm partitions outside it, 2.6 m
// high (a common office ceiling height).
constexpr double kOfficeRoomLength = 8.0;
constexpr double kOfficeRoomWidth = 6.0;
constexpr double kOfficeWallHeight = 2.6;
constexpr double kOfficeWallThickness = 0.1;

// Robot [m]: on the room's centre line, 1.2 m from the back wall, facing +x into the room.
constexpr double kOfficeRobotX = 1.2;

// Furniture slots [m]: 3 x 3 slots of 1.8 m from x = 2.4 (1.2 m ahead of the robot) to the
// far wall's 0.2 m aisle, and across y in [-2.7, 2.7] (0.3 m aisles along the side walls).
constexpr int kSlotColumns = 3;
constexpr int kSlotRows = 3;
constexpr double kSlotSide = 1.8;
constexpr double kSlotsStartX = 2.4;
constexpr double kSlotsStartY = -2.7;
constexpr double kSlotMargin = 0.05;  // kept free inside each slot's border

// How many of each: 2-3 tables and 3-4 chairs; boxes fill the remaining slots (2-4).
constexpr int kMinTables = 2;
constexpr int kMinChairs = 3;
// Tables stand square to the walls, turned by up to this much [rad] either way.
constexpr double kTableSkew = model::deg_to_rad(10.0);
// Cardboard boxes [m]: each edge between 20 and 50 cm.
constexpr double kBoxMinSide = 0.2;
constexpr double kBoxMaxSide = 0.5;

// Seeded draws computed from the raw engine output. The standard fixes mt19937_64's sequence
// but not the algorithms of uniform_real_distribution or shuffle, so using those would let a
// seed furnish the room differently under another standard library.
double uniform(std::mt19937_64& rng, double low, double high) {
  const double unit = static_cast<double>(rng() >> 11) * 0x1.0p-53;  // 53 bits in [0, 1)
  return low + (high - low) * unit;
}

// An integer in [low, high]; the modulo bias is below 1e-17 for ranges this small.
int uniform_int(std::mt19937_64& rng, int low, int high) {
  const auto span = static_cast<std::uint64_t>(high - low + 1);
  return low + static_cast<int>(rng() % span);
}

// Fisher-Yates with the draw above.
void shuffle(std::vector<int>& values, std::mt19937_64& rng) {
  for (int i = static_cast<int>(values.size()) - 1; i > 0; --i) {
    std::swap(values[static_cast<std::size_t>(i)],
              values[static_cast<std::size_t>(uniform_int(rng, 0, i))]);
  }
}

// A pose for a piece of half-extents (half_x, half_y) [m] turned by `yaw` [rad], shifted at
// random as far as it still fits inside `slot`'s margin.
model::Pose3 place_in_slot(int slot, double half_x, double half_y, double yaw,
                           std::mt19937_64& rng) {
  const double centre_x = kSlotsStartX + (slot % kSlotColumns + 0.5) * kSlotSide;
  const double centre_y = kSlotsStartY + (slot / kSlotColumns + 0.5) * kSlotSide;
  const double c = std::abs(std::cos(yaw));
  const double s = std::abs(std::sin(yaw));
  const double free_half = kSlotSide / 2 - kSlotMargin;
  const double slack_x = std::max(0.0, free_half - (c * half_x + s * half_y));
  const double slack_y = std::max(0.0, free_half - (s * half_x + c * half_y));
  // One draw per statement: the order in which function arguments are evaluated is
  // unspecified, and the draws must come in a fixed order.
  const double shift_x = uniform(rng, -slack_x, slack_x);
  const double shift_y = uniform(rng, -slack_y, slack_y);
  return floor_pose(centre_x + shift_x, centre_y + shift_y, yaw);
}

void add_room(model::Scene& scene) {
  add_object(
      scene, "floor",
      floor_rectangle({{0, -kOfficeRoomWidth / 2}, {kOfficeRoomLength, kOfficeRoomWidth / 2}}, 0));
  const double t = kOfficeWallThickness;
  const double y = kOfficeRoomWidth / 2;
  // The side walls run past the end walls so the corners are closed.
  add_object(scene, "wall_back", aligned_box({-t, -y, 0}, {0, y, kOfficeWallHeight}));
  add_object(
      scene, "wall_front",
      aligned_box({kOfficeRoomLength, -y, 0}, {kOfficeRoomLength + t, y, kOfficeWallHeight}));
  add_object(scene, "wall_left",
             aligned_box({-t, y, 0}, {kOfficeRoomLength + t, y + t, kOfficeWallHeight}));
  add_object(scene, "wall_right",
             aligned_box({-t, -y - t, 0}, {kOfficeRoomLength + t, -y, kOfficeWallHeight}));
}

}  // namespace

model::Scene make_office_scene(std::uint64_t seed) {
  model::Scene scene;
  scene.name = "office";
  scene.T_world_robot = floor_pose(kOfficeRobotX, 0, 0);
  add_room(scene);

  std::mt19937_64 rng(seed);
  const int tables = kMinTables + uniform_int(rng, 0, 1);
  const int chairs = kMinChairs + uniform_int(rng, 0, 1);
  std::vector<int> slots(kSlotColumns * kSlotRows);
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
  shuffle(slots, rng);

  std::size_t next_slot = 0;
  for (int i = 1; i <= tables; ++i) {
    const double square_yaw = uniform_int(rng, 0, 1) * std::numbers::pi / 2;
    const double yaw = square_yaw + uniform(rng, -kTableSkew, kTableSkew);
    // Every table's footprint keeps room for the cable on its -y side (and, for symmetry,
    // the same on its +y side).
    const model::Pose3 T_world_table = place_in_slot(slots[next_slot++], kTableLength / 2,
                                                     kTableDepth / 2 + kCableReach, yaw, rng);
    add_office_table(scene, "table_" + std::to_string(i), T_world_table);
    if (i == 1) add_hanging_cable(scene, T_world_table);
  }
  for (int i = 1; i <= chairs; ++i) {
    const double yaw = uniform(rng, 0, 2 * std::numbers::pi);
    add_office_chair(scene, "chair_" + std::to_string(i),
                     place_in_slot(slots[next_slot++], kChairReach, kChairReach, yaw, rng));
  }
  for (int i = 1; next_slot < slots.size(); ++i) {
    model::Vec3 size;
    for (int axis = 0; axis < 3; ++axis) size[axis] = uniform(rng, kBoxMinSide, kBoxMaxSide);
    const double yaw = uniform(rng, 0, std::numbers::pi / 2);
    model::Pose3 T_world_box =
        place_in_slot(slots[next_slot++], size.x() / 2, size.y() / 2, yaw, rng);
    T_world_box.translate(model::Vec3(0, 0, size.z() / 2));
    add_object(scene, "box_" + std::to_string(i), box_mesh(size, T_world_box));
  }
  return scene;
}

}  // namespace rigdesign::sim
