// Issue 15: pose ranges in catalog slots.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/select/buried_poses.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

std::string catalog_with(const std::string& slot_pose) {
  return "name: Ranges\nsensor_library: " + source_path("sensors.yaml") + R"(
body: {radius: 0.45, height: 1.0}
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

}  // namespace

TEST_CASE("pose ranges: every combination, the last axis fastest, labelled", "[io][select]") {
  TempFolder folder;
  const model::Catalog catalog = io::load_catalog(
      folder.write("c.yaml", catalog_with("{xyz: [0.46, 0, {min: 0.2, max: 0.8, step: 0.2}], "
                                          "rpy_deg: [0, {min: 0, max: 40, step: 10}, 0]}")));
  const model::MountingSlot& slot = catalog.slots.front();
  // z in {0.2, 0.4, 0.6, 0.8} x pitch in {0, 10, 20, 30, 40}: 20 poses.
  REQUIRE(slot.poses.size() == 20);
  // Pose 7 = z index 1 (0.4 m), pitch index 2 (20 deg).
  const model::Pose3 expected = model::pose_from_xyz_rpy(
      model::Vec3(0.46, 0.0, 0.4), model::Vec3(0.0, 20 * std::acos(-1.0) / 180, 0.0));
  CHECK((slot.poses[7].T_robot_sensor.matrix() - expected.matrix()).norm() < 1e-12);
  CHECK(slot.poses[7].label == "z 0.4 m, pitch 20 deg");
  CHECK(slot.poses[0].label == "z 0.2 m, pitch 0 deg");
}

TEST_CASE("pose ranges: positions inside the body are left out by select and counted",
          "[io][select]") {
  TempFolder folder;
  // x in {0, 0.2, 0.4, 0.6} at z 0.5 on a cylinder of radius 0.45 m and height 1 m: the first
  // three inside, the last outside.
  const model::Catalog catalog = io::load_catalog(
      folder.write("c.yaml", catalog_with("{xyz: [{min: 0, max: 0.6, step: 0.2}, 0, 0.5]}")));
  REQUIRE(catalog.slots.front().poses.size() == 4);  // the loader keeps every pose
  const select::BuriedPoses buried = select::find_buried_poses(catalog);
  CHECK(buried.buried.front() == std::vector<bool>{true, true, true, false});
  REQUIRE(buried.left_out.size() == 1);
  CHECK(buried.left_out.front().count() == 3);
  CHECK(select::describe(buried.left_out.front())
            .find("front: 3 of 4 poses, 3 inside the robot "
                  "body") == 0);
}

TEST_CASE("pose ranges: bad ranges are errors at the range", "[io][select]") {
  TempFolder folder;
  const auto error_of = [&](const std::string& pose) {
    try {
      io::load_catalog(folder.write("bad.yaml", catalog_with(pose)));
    } catch (const model::InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  // The slot is on line 10 of catalog_with's text; the ranges sit in it.
  CHECK_THAT(error_of("{xyz: [0.46, 0, {min: 0.2, max: 0.8, step: 0.25}]}"),
             Catch::Contains("bad.yaml:10:") && Catch::Contains("slots[0].pose.xyz[2].step") &&
                 Catch::Contains("does not divide"));
  CHECK_THAT(error_of("{xyz: [0.46, 0, {min: 0.8, max: 0.2, step: 0.2}]}"),
             Catch::Contains("xyz[2].min") && Catch::Contains("is above max"));
  CHECK_THAT(error_of("{xyz: [0.46, 0, {min: 0.2, max: 0.8, step: 0}]}"),
             Catch::Contains("xyz[2].step") && Catch::Contains("is not positive"));
  CHECK_THAT(error_of("{xyz: [0.46, 0, {min: 0.2, max: 0.8}]}"),
             Catch::Contains("xyz[2].step") && Catch::Contains("missing"));
  // Found by fuzzing: 0.1 to 7.8e8 m in steps of 0.05 names 1.6e10 values (an int overflow);
  // refused before any is made.
  CHECK_THAT(error_of("{xyz: [0.46, 0, {min: 0.1, max: 777777770.3, step: 0.05}]}"),
             Catch::Contains("xyz[2].step") && Catch::Contains("gives 1.56e+10 values") &&
                 Catch::Contains("at most 400 poses per slot"));
  // 21 x 21 positions: more than a slot may hold.
  CHECK_THAT(
      error_of("{xyz: [{min: 0.5, max: 2.5, step: 0.1}, {min: -1, max: 1, step: 0.1}, 0.5]}"),
      Catch::Contains("441 poses in one slot"));
}
