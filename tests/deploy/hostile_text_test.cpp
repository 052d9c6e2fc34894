// Issue 31 item 2: text a user controls (the rig's name, a folder's name, a description's
// link names) reaches the exported files, the JUnit report and the HTML report only quoted
// or escaped. Every file is read back with Python's parsers (tests/data/hostile/
// parse_export.py), never with rigdesign's own readers.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

// A name that breaks every format written raw: quotes, markup, a comment closer, a CR and a
// LF each followed by a key, a control character.
const std::string kHostile = "evil \"name' <&> -- x\r injected: true\n injected: 1 #\x01";

bool python_has_yaml() {
  return std::system("python3 -c 'import yaml' > /dev/null 2>&1") == 0;
}

std::string read(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::string yaml_double_quoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (c == '\n') {
      quoted += "\\n";
    } else if (c == '\r') {
      quoted += "\\r";
    } else if (byte < 0x20) {
      quoted += "\\x0" + std::to_string(byte);  // only \x01 here
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

}  // namespace

TEST_CASE("hostile names reach exported files, JUnit and HTML only escaped", "[deploy]") {
  if (!python_has_yaml()) {
    WARN("python3 with PyYAML is missing (scripts/setup.sh installs python3-yaml): not run");
    return;
  }
  TempFolder folder;
  // The description's plate link carries the hostile characters XML allows in a name.
  const std::string link = "plate\"<&>'--";
  const std::string link_attribute = "plate&quot;&lt;&amp;&gt;&apos;--";
  const std::string description = folder.write(
      "robot.urdf",
      "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n"
      "<link name=\"base_link\"><collision><geometry><box size=\"0.4 0.4 0.3\"/></geometry>"
      "</collision></link>\n<link name=\"" +
          link_attribute +
          "\"/>\n"
          "<joint name=\"j\" type=\"fixed\"><parent link=\"base_link\"/><child link=\"" +
          link_attribute + "\"/><origin xyz=\"0 0 0.4\"/></joint>\n</robot>\n");
  // The rig lives in a folder whose name is hostile too (paths reach the headers), with a
  // Latin-1 byte that is not UTF-8.
  const std::string odd_folder = folder.path() + "/we\"ird <&> -- dir\r\xe9";
  std::filesystem::create_directories(odd_folder);
  const std::string rig = odd_folder + "/rig.yaml";
  std::ofstream(rig) << "name: " << yaml_double_quoted(kHostile)
                     << "\nsensor_library: " << source_path("sensors.yaml")
                     << "\nrobot:\n  description: " << description
                     << "\n  base_link: base_link\narea_height: 0.5\ndistance_of_interest: 2.0\n"
                     << "mounts:\n"
                     << "  - {id: lidar, sensor: rplidar_a1m8, mode: 5_5hz,"
                     << " pose: {urdf_link: " << yaml_double_quoted(link) << "}}\n"
                     << "  - {id: cam, sensor: realsense_d435, mode: z16_848x480_30,"
                     << " pose: {xyz: [0.2, 0, 0.5]}}\n";
  const std::string out = folder.path() + "/export";
  const CliResult exported = run_cli({"export", rig, "--to", out});
  INFO(exported.out << exported.err);
  REQUIRE(exported.exit_code == 0);
  const std::string command = "python3 " + source_path("tests/data/hostile/parse_export.py") +
                              " '" + out + "' lidar,cam base_link";
  CHECK(std::system(command.c_str()) == 0);

  const std::string junit = folder.path() + "/junit.xml";
  const CliResult checked = run_cli({"check", rig, "--format", "junit", "--output", junit});
  INFO(checked.out << checked.err);
  CHECK(checked.exit_code == 0);
  CHECK(
      std::system(("python3 -c \"import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])\" '" +
                   junit + "'")
                      .c_str()) == 0);

  const std::string report = folder.path() + "/report";
  REQUIRE(run_cli({"report", rig, "--out", report}).exit_code == 0);
  const std::string page = read(report + "/report.html");
  CHECK(page.find("<&>") == std::string::npos);  // the name's markup arrives as entities
  CHECK(page.find("&lt;&amp;&gt;") != std::string::npos);
}

TEST_CASE(
    "mount ids that name each other's frames (cam beside cam_optical) export distinct "
    "joints (06)",
    "[deploy]") {
  if (!python_has_yaml()) {
    WARN("python3 with PyYAML is missing (scripts/setup.sh installs python3-yaml): not run");
    return;
  }
  TempFolder folder;
  const std::string rig = folder.write(
      "rig.yaml", "name: ids\nsensor_library: " + source_path("sensors.yaml") +
                      "\nbody: {radius: 0.45, height: 1.0}\ndistance_of_interest: 3.5\nmounts:\n"
                      "  - {id: cam, sensor: realsense_d435, mode: z16_848x480_30,"
                      " pose: {xyz: [0.46, 0, 0.3]}}\n"
                      "  - {id: cam_optical, sensor: rplidar_a1m8, mode: 5_5hz,"
                      " pose: {xyz: [0, 0, 1.1]}}\n");
  const std::string out = folder.path() + "/export";
  const CliResult exported = run_cli({"export", rig, "--to", out});
  INFO(exported.out << exported.err);
  REQUIRE(exported.exit_code == 0);
  // The rig has no description: every joint hangs from REP-105's base_footprint.
  CHECK(std::system(("python3 " + source_path("tests/data/hostile/parse_export.py") + " '" + out +
                     "' cam,cam_optical base_footprint")
                        .c_str()) == 0);
}
