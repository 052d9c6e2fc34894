// B1, a sensor buried in the body (issue 52 item 1). The Jackal as its description ships it:
// the chassis box by hand from jackal.urdf.xacro, lines 13-15 give 0.420 x 0.310 x 0.184 m,
// line 112 centres it chassis_height / 2 above chassis_link, which base_link_joint puts at
// base_link, 0.0655 m above the floor (the rig's base_link_height). In the robot frame the box
// spans x in [-0.21, 0.21], y in [-0.155, 0.155], z in [0.0655, 0.2495]; its <collision>
// element is line 111. The cylinder case: a 0.4 m radius, 1 m body (fixture_files.hpp).
#include <catch2/catch.hpp>
#include <string>

#include "support/cli_runner.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

std::string jackal_with(const std::string& extra_mount) {
  return "name: Jackal\nsensor_library: " + source_path("sensors.yaml") +
         "\nrobot:\n  description: " +
         source_path("rigs/robots/jackal_description/urdf/jackal.urdf.xacro") +
         "\n  env: {JACKAL_LASER: 1, JACKAL_LASER_3D: 1}\n  package_paths: [" +
         source_path("rigs/robots") +
         "]\n  base_link: base_link\n  base_link_height: 0.0655\narea_height: 0.25\n"
         "distance_of_interest: 3.0\nmounts:\n  - {id: front_laser, sensor: sick_lms100, "
         "mode: res_0.5deg_25hz, pose: {urdf_link: front_laser}}\n" +
         extra_mount;
}

std::string with_d435_at(const std::string& xyz) {
  return jackal_with(
      "  - {id: d435, sensor: realsense_d435, mode: z16_848x480_30, pose: {xyz: " + xyz + "}}\n");
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("a camera buried in the Jackal's chassis box fails B1, naming the link and its line",
          "[geometry]") {
  TempFolder folder;
  // (0.10, 0, 0.15): inside the box by the bounds above. The rig file's mount is line 13.
  const CliResult buried =
      run_cli({"check", folder.write("buried.yaml", with_d435_at("[0.10, 0, 0.15]"))});
  INFO(buried.out << buried.err);
  CHECK(buried.exit_code == 1);
  CHECK(has(buried.out, "B1"));
  CHECK(has(buried.out, "inside the collision geometry of link 'chassis_link'"));
  CHECK(has(buried.out, "jackal.urdf.xacro:111"));
  CHECK(has(buried.out, "buried.yaml:13:"));
  // It sees nothing through the chassis: the metrics warn and its coverage is nil.
  const CliResult metrics = run_cli({"metrics", folder.path() + "/buried.yaml"});
  INFO(metrics.out << metrics.err);
  CHECK(metrics.exit_code == 0);
  CHECK(has(metrics.out, "chassis_link"));
  // (-0.15, 0.10, 0.2625): above the box's top (0.2495) and behind the VLP-16 tower, the
  // D435's 25 mm tall housing standing on it (its origin mid-height: B2 passes).
  const CliResult above =
      run_cli({"check", folder.write("above.yaml", with_d435_at("[-0.15, 0.10, 0.2625]"))});
  INFO(above.out << above.err);
  CHECK(above.exit_code == 0);
}

TEST_CASE("the Jackal's own sensors sit in their housings: its rig passes B1", "[geometry]") {
  // Wherever the description puts them (the VLP-16 on its tower, the SICK on its bracket),
  // no part but a sensor's own housing holds its origin.
  const CliResult result = run_cli({"check", source_path("rigs/jackal.yaml")});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 0);
  CHECK(has(result.out, "B1"));
}

TEST_CASE("a mount inside a cylinder body fails B1 at its pose", "[geometry]") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  std::string rig = kRig;
  // x 0.1 m at z 0.5 m: inside the 0.4 m radius, 1 m tall body.
  rig.replace(rig.find("xyz: [0.41, 0.0, 0.5]"), 21, "xyz: [0.1, 0.0, 0.5]");
  const CliResult result = run_cli({"check", folder.write("rig.yaml", rig)});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 1);
  // The `pose` of mount `front` is line 12 of kRig.
  CHECK(has(result.out, "rig.yaml:12:"));
  CHECK(has(result.out, "inside the robot body"));
}

TEST_CASE("a stated housing must be a sensor's own: the Jackal's chassis and base are refused",
          "[geometry]") {
  TempFolder folder;
  // chassis_link carries the wheels' collision below it (jackal.urdf.xacro: the wheel joints'
  // parent is chassis_link); base_link carries the robot frame.
  for (const auto& [link, why] :
       {std::pair{"chassis_link", "has other links' collision geometry below it"},
        std::pair{"base_link", "has no collision geometry"}}) {
    const CliResult result = run_cli(
        {"check", folder.write(std::string(link) + ".yaml",
                               with_d435_at("[0.10, 0, 0.15], rpy_deg: [0, 0, 0], housing: " +
                                            std::string(link)))});
    INFO(result.out << result.err);
    CHECK(result.exit_code == 2);
    CHECK(has(result.out + result.err, "mounts[1].pose.housing"));
    CHECK(has(result.out + result.err, why));
  }
}
