#include <catch2/catch.hpp>

#include "rigdesign/io/config/rig_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

TEST_CASE("a URDF-posed mount equals the same pose written in the rig file") {
  // rigs/urdf/ur_cleaner.urdf builds each pose as a chain (base_link 5 cm up, brackets that
  // yaw, sensor links that pitch); ur_cleaner.yaml writes the composed xyz and rpy directly.
  const model::Rig by_hand = io::load_rig(source_path("rigs/ur_cleaner.yaml"));
  const model::Rig from_urdf = io::load_rig(source_path("rigs/ur_cleaner_from_urdf.yaml"));
  REQUIRE(by_hand.mounts.size() == from_urdf.mounts.size());
  for (std::size_t i = 0; i < by_hand.mounts.size(); ++i) {
    INFO(by_hand.mounts[i].id);
    CHECK(from_urdf.mounts[i].id == by_hand.mounts[i].id);
    CHECK(from_urdf.mounts[i].T_robot_sensor.isApprox(by_hand.mounts[i].T_robot_sensor, 1e-9));
  }
}

TEST_CASE("URDF problems are located errors") {
  TempFolder folder;
  const std::string urdf = folder.write("robot.urdf", R"(<robot name="r">
  <link name="base_footprint"/><link name="cam"/>
  <joint name="j" type="fixed"><parent link="base_footprint"/><child link="cam"/>
    <origin xyz="0.3 0 0.2" rpy="0 0 0"/></joint>
</robot>)");
  const std::string head =
      "name: r\nurdf: {file: robot.urdf}\nbody: {radius: 0.25, height: 0.5}\n"
      "distance_of_interest: 2.0\nmounts:\n  - id: m\n    sensor: cam\n"
      "    mode: m30\n";
  SECTION("an unknown link") {
    const std::string rig = folder.write("rig.yaml", head + "    pose: {urdf_link: camera}\n");
    const CliResult result = run_cli({"check", rig});
    CHECK(result.exit_code == 2);
    CHECK(result.out.find("rig.yaml:9:") != std::string::npos);
    CHECK(result.out.find("mounts[0].pose.urdf_link: no link 'camera' in the URDF") !=
          std::string::npos);
  }
  SECTION("an unreadable URDF") {
    std::string text = head + "    pose: {urdf_link: cam}\n";
    text.replace(text.find("robot.urdf"), 10, "nothere.urdf");
    const CliResult result = run_cli({"check", folder.write("rig.yaml", text)});
    CHECK(result.exit_code == 2);
    CHECK(result.out.find("rig.yaml:2:") != std::string::npos);
    CHECK(result.out.find("urdf.file: names") != std::string::npos);
  }
  SECTION("a file that is not XML names its line and the reason") {
    folder.write("robot.urdf", "<robot>\n<link>\n</robot>");
    const CliResult result =
        run_cli({"check", folder.write("rig.yaml", head + "    pose: {urdf_link: cam}\n")});
    CHECK(result.exit_code == 2);
    CHECK(result.out.find("robot.urdf:2:") != std::string::npos);  // <link> opened, never closed
    CHECK(result.out.find("is not well-formed XML") != std::string::npos);
  }
  SECTION("XML that is not a URDF says why") {
    folder.write("robot.urdf", R"(<robot name="r"><link name="a"/>
  <joint name="j" type="fixed"><parent link="a"/></joint></robot>)");
    const CliResult result =
        run_cli({"check", folder.write("rig.yaml", head + "    pose: {urdf_link: cam}\n")});
    CHECK(result.exit_code == 2);
    CHECK(result.out.find("is not a valid URDF: ") != std::string::npos);
    CHECK(result.out.find("child") != std::string::npos);
  }
}
