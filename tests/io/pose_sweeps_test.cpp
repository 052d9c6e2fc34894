// Issue 55 item 4: catalog slots whose position sweeps a segment, an arc, or a face or edge
// of a description link's collision box. Positions are checked against hand computations.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rotation.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

const double kPi = std::acos(-1.0);

// A catalog of one D435 slot at `slot_pose` on `robot` (a body or a robot description).
std::string catalog_on(const std::string& robot, const std::string& slot_pose) {
  return "name: Sweeps\nsensor_library: " + source_path("sensors.yaml") + "\n" + robot + R"(
distance_of_interest: 3.0
reference_machine: test
filtering_seconds_per_point: 0
sensors:
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
slots:
  - {id: front, pose: )" +
         slot_pose + R"(, allows: [realsense_d435]}
transfer:
  - {id: onboard, capacity_bps: 3.0e9, price_usd: 0}
cpus:
  - {id: small, cores: 3.0, price_usd: 300}
)";
}

std::string cylinder_catalog(const std::string& slot_pose) {
  return catalog_on("body: {radius: 0.2, height: 0.3}", slot_pose);
}

// The Jackal as rigs/jackal.yaml describes it (both laser accessories).
std::string jackal_catalog(const std::string& slot_pose) {
  return catalog_on("robot:\n  description: " +
                        source_path("rigs/robots/jackal_description/urdf/jackal.urdf.xacro") +
                        "\n  env: {JACKAL_LASER: 1, JACKAL_LASER_3D: 1}\n  package_paths: [" +
                        source_path("rigs/robots") +
                        "]\n  base_link: base_link\n  base_link_height: 0.0655",
                    slot_pose);
}

model::Vec3 position(const model::SlotPose& pose) {
  return pose.T_robot_sensor.translation();
}

}  // namespace

TEST_CASE("a slot along a segment: positions step apart, both ends included", "[io][select]") {
  TempFolder folder;
  const model::Catalog catalog = io::load_catalog(folder.write(
      "c.yaml", cylinder_catalog("{along: {from: [0.21, -0.1, 0.25], to: [0.21, 0.1, 0.25], "
                                 "step: 0.05}, rpy_deg: [0, {min: 10, max: 30, step: 10}, 0]}")));
  const model::MountingSlot& slot = catalog.slots.front();
  // 0.2 m / 0.05 m = 4 steps: 5 positions, each with pitch 10, 20, 30 deg.
  REQUIRE(slot.poses.size() == 15);
  CHECK((position(slot.poses[0]) - model::Vec3(0.21, -0.1, 0.25)).norm() < 1e-12);
  CHECK((position(slot.poses[14]) - model::Vec3(0.21, 0.1, 0.25)).norm() < 1e-12);
  // Pose 7: position 2 (y = 0), pitch 20 deg.
  const model::Pose3 expected =
      model::pose_from_xyz_rpy(model::Vec3(0.21, 0.0, 0.25), model::Vec3(0, 20 * kPi / 180, 0));
  CHECK((slot.poses[7].T_robot_sensor.matrix() - expected.matrix()).norm() < 1e-12);
  CHECK(slot.poses[7].label == "(0.21, 0, 0.25) m, pitch 20 deg");
  // Only the orientation is a range the refinement may move.
  REQUIRE(slot.ranges.size() == 1);
  CHECK(slot.ranges[0].axis == 4);
}

TEST_CASE("a slot on an arc faces outward: yaw is the azimuth plus the offset", "[io][select]") {
  TempFolder folder;
  const model::Catalog catalog = io::load_catalog(folder.write(
      "c.yaml", cylinder_catalog("{arc: {centre: [0, 0, 0.25], radius: 0.21, from_deg: -30, "
                                 "to_deg: 30, step_deg: 15}, rpy_deg: [0, 20, 5]}")));
  const model::MountingSlot& slot = catalog.slots.front();
  REQUIRE(slot.poses.size() == 5);
  // Azimuth 15 deg: (0.21 cos 15, 0.21 sin 15, 0.25); yaw 15 + 5 = 20 deg.
  const double azimuth = 15 * kPi / 180;
  const model::Pose3 expected = model::pose_from_xyz_rpy(
      model::Vec3(0.21 * std::cos(azimuth), 0.21 * std::sin(azimuth), 0.25),
      model::Vec3(0, 20 * kPi / 180, 20 * kPi / 180));
  CHECK((slot.poses[3].T_robot_sensor.matrix() - expected.matrix()).norm() < 1e-12);
  CHECK(slot.poses[3].label.rfind("azimuth 15 deg, (", 0) == 0);
  CHECK(slot.ranges.empty());
}

TEST_CASE("a slot on an arc refuses a yaw range while facing outward", "[io][select]") {
  TempFolder folder;
  const std::string file = folder.write(
      "c.yaml", cylinder_catalog("{arc: {centre: [0, 0, 0.25], radius: 0.21, from_deg: 0, "
                                 "to_deg: 90, step_deg: 30}, rpy_deg: [0, 0, {min: 0, max: 10, "
                                 "step: 5}]}"));
  CHECK_THROWS_WITH(io::load_catalog(file),
                    Catch::Contains("rpy_deg") && Catch::Contains("yaw range for an arc"));
}

TEST_CASE("a slot along the front edge of the Jackal's chassis top", "[io][select]") {
  TempFolder folder;
  const model::Catalog catalog = io::load_catalog(folder.write(
      "c.yaml", jackal_catalog("{on_link: {link: chassis_link, face: top, edge: front, "
                               "step: 0.05, inset: 0.005}, rpy_deg: [0, 20, 0]}")));
  const model::MountingSlot& slot = catalog.slots.front();
  // jackal.urdf.xacro: chassis_link's collision box is 0.420 x 0.310 x 0.184 m, its origin
  // 0.092 m above chassis_link = base_link, which is 0.0655 m above the floor: top z 0.2495
  // (positions sit 1 mm proud of it: 0.2505), front x 0.21 - 0.005 inset = 0.205; y from
  // -0.155 + 0.005 to 0.15 every 0.05: 7 points.
  REQUIRE(slot.poses.size() == 7);
  CHECK((position(slot.poses[0]) - model::Vec3(0.205, -0.15, 0.2505)).norm() < 1e-9);
  CHECK((position(slot.poses[6]) - model::Vec3(0.205, 0.15, 0.2505)).norm() < 1e-9);
}

TEST_CASE("a swept slot: bad paths are errors naming the field", "[io][select]") {
  TempFolder folder;
  SECTION("a step that does not divide the segment") {
    const std::string file = folder.write(
        "c.yaml", cylinder_catalog("{along: {from: [0.21, 0, 0.2], to: [0.21, 0.1, 0.2], "
                                   "step: 0.03}}"));
    CHECK_THROWS_WITH(io::load_catalog(file),
                      Catch::Contains("along.step") && Catch::Contains("does not divide"));
  }
  SECTION("a link without collision geometry") {
    const std::string file = folder.write(
        "c.yaml", jackal_catalog("{on_link: {link: no_such_link, face: top, step: 0.05}}"));
    CHECK_THROWS_WITH(io::load_catalog(file),
                      Catch::Contains("on_link.link") && Catch::Contains("chassis_link"));
  }
  SECTION("xyz and a path together") {
    const std::string file = folder.write(
        "c.yaml", cylinder_catalog("{xyz: [0.21, 0, 0.2], along: {from: [0.21, 0, 0.2], "
                                   "to: [0.21, 0.1, 0.2], step: 0.05}}"));
    CHECK_THROWS_WITH(io::load_catalog(file), Catch::Contains("xyz"));
  }
}
