// Bad input never crashes: each case gets exit code 2 and a message naming the file, the
// line (found here by searching the file's text, independently of the loader) and the field.
#include <catch2/catch.hpp>
#include <filesystem>

#include "support/cli_runner.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

struct BadCase {
  const char* name;
  const char* file;  // "sensors.yaml", "rig.yaml" or "req.yaml"
  std::string from;  // text input_replaced in the valid fixture
  std::string to;
  std::string field;        // field path the message must name
  std::string line_marker;  // text on the line the message must point at
};

std::string input_replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("the valid fixture passes check") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  const std::string rig = folder.write("rig.yaml", kRig);
  const CliResult result = run_cli({"check", rig});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 0);
}

TEST_CASE("bad input: exit 2 with file:line:col and the field") {
  const std::vector<BadCase> cases = {
      {"wrong type", "rig.yaml", "distance_of_interest: 3.0", "distance_of_interest: far",
       "distance_of_interest", "distance_of_interest: far"},
      {"unknown field", "rig.yaml", "    mode: m30\n", "    mode: m30\n    colour: red\n",
       "mounts[0].colour", "colour: red"},
      {"unknown sensor", "rig.yaml", "sensor: cam", "sensor: camera", "mounts[0].sensor",
       "sensor: camera"},
      {"unknown mode", "rig.yaml", "mode: m30", "mode: m60", "mounts[0].mode", "mode: m60"},
      {"negative range", "sensors.yaml", "range: {min: 0.1,", "range: {min: -0.1,",
       "sensors[0].modes[0].range.min", "min: -0.1"},
      {"min range not below max", "sensors.yaml", "{min: 0.5, max: 50}", "{min: 60, max: 50}",
       "sensors[1].modes[0].range.min", "min: 60"},
      {"NaN pose", "rig.yaml", "xyz: [0.41, 0.0, 0.5]", "xyz: [0.41, .nan, 0.5]",
       "mounts[0].pose.xyz[1]", ".nan"},
      {"infinite pose", "rig.yaml", "xyz: [0.0, 0.0, 1.05]", "xyz: [0.0, 0.0, .inf]",
       "mounts[1].pose.xyz[2]", ".inf"},
      {"pose beyond 1e8 m (reliability 20)", "rig.yaml", "xyz: [0.0, 0.0, 1.05]",
       "xyz: [0.0, 0.0, 1e300]", "mounts[1].pose.xyz", "1e300"},
      {"distance beyond 1e8 m", "rig.yaml", "distance_of_interest: 3.0",
       "distance_of_interest: 2e8", "distance_of_interest", "distance_of_interest: 2e8"},
      {"FOV angle 0", "sensors.yaml", "horizontal_deg: 60", "horizontal_deg: 0",
       "sensors[0].modes[0].fov.horizontal_deg", "horizontal_deg: 0"},
      {"FOV angle over 360", "sensors.yaml", "horizontal_deg: 360", "horizontal_deg: 400",
       "sensors[1].modes[0].fov.horizontal_deg", "horizontal_deg: 400"},
      {"pyramid of 180 degrees", "sensors.yaml", "vertical_deg: 40", "vertical_deg: 180",
       "sensors[0].modes[0].fov.vertical_deg", "vertical_deg: 180"},
      {"duplicate mount ids", "rig.yaml", "id: top", "id: front", "mounts[1].id",
       "id: front\n    sensor: spin"},
      {"empty rig", "rig.yaml", kRig.substr(kRig.find("mounts:")), "mounts: []\n", "mounts",
       "mounts: []"},
      {"requirement out of range", "req.yaml", "min_floor_coverage: 0.0", "min_floor_coverage: 1.5",
       "sectors[0].min_floor_coverage", "min_floor_coverage: 1.5"},
      {"negative frequency", "sensors.yaml", "frequency: 30", "frequency: -30",
       "sensors[0].modes[0].frequency", "frequency: -30"},
      {"key given twice", "rig.yaml", "distance_of_interest: 3.0",
       "distance_of_interest: 3.0\ndistance_of_interest: 4.0", "distance_of_interest",
       "distance_of_interest: 4.0"},
      {"unknown lighting condition", "req.yaml", "lighting: [dark, indoor]",
       "lighting: [dark, moonlight]", "lighting[1]", "moonlight"},
      {"missing required field", "rig.yaml", "  height: 1.0\n", "", "body.height", "body:"},
      {"sensor library that does not exist", "rig.yaml", "sensor_library: sensors.yaml",
       "sensor_library: nowhere.yaml", "sensor_library", "nowhere.yaml"},
      {"unknown technology", "sensors.yaml", "technology: tof", "technology: sonar",
       "sensors[0].technology", "sonar"},
      {"distance of interest inside the body", "rig.yaml", "distance_of_interest: 3.0",
       "distance_of_interest: 0.3", "distance_of_interest", "distance_of_interest: 0.3"},
      {"negative speed", "req.yaml", "max_speed: 1.0", "max_speed: -1", "robot_speed.max_speed",
       "max_speed: -1"},
      {"body height of zero", "rig.yaml", "  height: 1.0\n", "  height: 0\n", "body.height",
       "height: 0"},
      {"noise coefficient that is a list", "sensors.yaml", "noise: {a: 0.03}", "noise: {a: [1]}",
       "sensors[1].modes[0].noise.a", "noise: {a: [1]}"},
  };
  for (const BadCase& bad : cases) {
    DYNAMIC_SECTION(bad.name) {
      TempFolder folder;
      const std::string library = bad.file == std::string("sensors.yaml")
                                      ? input_replaced(kLibrary, bad.from, bad.to)
                                      : kLibrary;
      const std::string rig_text =
          bad.file == std::string("rig.yaml") ? input_replaced(kRig, bad.from, bad.to) : kRig;
      const std::string requirements = bad.file == std::string("req.yaml")
                                           ? input_replaced(kRequirements, bad.from, bad.to)
                                           : kRequirements;
      folder.write("sensors.yaml", library);
      folder.write("req.yaml", requirements);
      const std::string rig = folder.write("rig.yaml", rig_text);
      const std::string& bad_text = bad.file == std::string("sensors.yaml") ? library
                                    : bad.file == std::string("rig.yaml")   ? rig_text
                                                                            : requirements;
      const int line = line_of(bad_text, bad.line_marker);
      REQUIRE(line > 0);
      const std::string where = folder.path() + "/" + bad.file + ":" + std::to_string(line) + ":";

      const CliResult metrics = run_cli({"metrics", rig});
      INFO(metrics.err);
      CHECK(metrics.exit_code == 2);
      CHECK(metrics.out.empty());  // nothing half-written
      CHECK(metrics.err.find(where) != std::string::npos);
      CHECK(metrics.err.find(": " + bad.field + ": ") != std::string::npos);
      CHECK(metrics.err.find("(expected ") != std::string::npos);

      const CliResult check = run_cli({"check", rig});
      CHECK(check.exit_code == 2);
      CHECK(check.out.find(where) != std::string::npos);
    }
  }
}

// Mount ids become URDF link names, nav2 source keys and filter node names: anything but a ROS
// name is refused where it is written, so no exported file needs quoting or escaping.
TEST_CASE("a mount id that is not a ROS name is refused with file:line:col") {
  const std::vector<std::pair<std::string, std::string>> ids = {
      {"quote", "'fr\"ont'"},      {"angle bracket", "'fr<ont'"}, {"space", "'front cam'"},
      {"leading digit", "2front"}, {"hyphen", "front-cam"},       {"empty", "''"}};
  for (const auto& [name, id] : ids) {
    DYNAMIC_SECTION(name) {
      TempFolder folder;
      folder.write("sensors.yaml", kLibrary);
      folder.write("req.yaml", kRequirements);
      const std::string text = input_replaced(kRig, "id: front", "id: " + id);
      const std::string rig = folder.write("rig.yaml", text);
      // The value's line and column, found in the text written (1-based).
      const int line = line_of(text, "id: " + id);
      REQUIRE(line > 0);
      std::size_t line_start = 0;
      for (int i = 1; i < line; ++i) line_start = text.find('\n', line_start) + 1;
      const std::size_t column = text.find(id, line_start) - line_start + 1;
      const std::string where = folder.path() + "/rig.yaml:" + std::to_string(line) + ":" +
                                std::to_string(column) + ": mounts[0].id: ";
      const CliResult export_run = run_cli({"export", rig, "--to", folder.path() + "/out"});
      INFO(export_run.err);
      CHECK(export_run.exit_code == 2);
      CHECK(export_run.err.find(where) != std::string::npos);
      CHECK(export_run.err.find("is not a ROS name") != std::string::npos);
      CHECK_FALSE(std::filesystem::exists(folder.path() + "/out"));  // nothing half-written
    }
  }
  // A control character in the id: the JUnit report quoting it stays well-formed XML (XML 1.0
  // cannot hold U+0001, not even as a reference), with U+FFFD in its place.
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  const std::string rig =
      folder.write("rig.yaml", input_replaced(kRig, "id: front", "id: \"fr\\u0001ont\""));
  const CliResult junit = run_cli({"check", rig, "--format", "junit"});
  CHECK(junit.exit_code == 2);
  CHECK(junit.out.find('\x01') == std::string::npos);
  CHECK(junit.out.find("fr\xEF\xBF\xBDont") != std::string::npos);
}

// Radians typed into a degrees field (issue 30, item 7): 0.35 is 20 deg in radians. The rig
// still loads (2.5 deg tilts exist), but the warning names the field where it is written.
TEST_CASE("rpy_deg that looks like radians is a warning naming file:line:col") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  const std::string text = input_replaced(kRig, "rpy_deg: [0, 20, 0]", "rpy_deg: [0, 0.35, 0]");
  const std::string rig = folder.write("rig.yaml", text);
  const int line = line_of(text, "rpy_deg: [0, 0.35, 0]");
  REQUIRE(line > 0);
  const CliResult metrics = run_cli({"metrics", rig});
  INFO(metrics.out);
  CHECK(metrics.exit_code == 0);
  CHECK(metrics.out.find(folder.path() + "/rig.yaml:" + std::to_string(line) + ":") !=
        std::string::npos);
  CHECK(metrics.out.find("mounts[0].pose.rpy_deg") != std::string::npos);
  CHECK(metrics.out.find("looks like radians") != std::string::npos);
  CHECK(metrics.out.find("20.05") != std::string::npos);  // 0.35 rad in degrees
  // Whole degrees, or any angle beyond pi, read as meant.
  const std::string whole = folder.write(
      "whole.yaml", input_replaced(kRig, "rpy_deg: [0, 20, 0]", "rpy_deg: [0, 2.5, 90]"));
  CHECK(run_cli({"metrics", whole}).out.find("looks like radians") == std::string::npos);
}

TEST_CASE("bad input: missing file, YAML syntax error and an empty file") {
  TempFolder folder;
  SECTION("missing file") {
    const CliResult result = run_cli({"metrics", folder.path() + "/nope.yaml"});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("nope.yaml: file: cannot be opened") != std::string::npos);
  }
  SECTION("syntax error") {
    // An unclosed flow sequence: the parser reports where it gave up, line 3.
    const std::string rig = folder.write("rig.yaml", "name: x\nbody: [1, 2\nmounts: []\n");
    const CliResult result = run_cli({"metrics", rig});
    CHECK(result.exit_code == 2);
    // "<path>:<line>:<col>: (syntax): ..." with a line inside the 3-line file.
    const std::string prefix = rig + ":";
    REQUIRE(result.err.rfind(prefix, 0) == 0);
    const int line = std::stoi(result.err.substr(prefix.size()));
    CHECK((line >= 2 && line <= 4));
    CHECK(result.err.find(": (syntax): YAML syntax error") != std::string::npos);
  }
  SECTION("empty file") {
    const std::string rig = folder.write("rig.yaml", "");
    const CliResult result = run_cli({"metrics", rig});
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("rig.yaml:1:1: (document): is not a map") != std::string::npos);
  }
  SECTION("unknown option") {
    const CliResult result = run_cli({"metrics", "--frobnicate"});
    CHECK(result.exit_code == 2);
  }
}

TEST_CASE("a misspelt field is named with the field it was probably meant to be") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  std::string text = kRig;
  text.replace(text.find("    mode: m30\n"), 13, "    mode: m30\n    distance_of_interst: 2.0\n");
  const CliResult result = run_cli({"metrics", folder.write("rig.yaml", text)});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("mounts[0].distance_of_interst: unknown field (did you mean "
                        "'distance_of_interest'?) (expected one of: crosstalk, "
                        "distance_of_interest, id, mode, note, pose, recessed, ros, sensor, "
                        "throttle_hz, tolerance)") != std::string::npos);
}

TEST_CASE("pose.rpy (URDF's radians habit) is pointed at rpy_deg") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  std::string text = kRig;
  const std::string from = "rpy_deg: [0, 20, 0]";
  text.replace(text.find(from), from.size(), "rpy: [0, 0.349, 0]");
  const CliResult result = run_cli({"metrics", folder.write("rig.yaml", text)});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("mounts[0].pose.rpy: unknown field (did you mean 'rpy_deg'?)") !=
        std::string::npos);
}

// Issue 30 item 7: degrees in a radians field, radians in a degrees field, near misses.
TEST_CASE("a sector of +-0.52 looks like radians: a warning at the sector") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  const std::string requirements =
      input_replaced(kRequirements, "from_deg: -45, to_deg: 45", "from_deg: -0.52, to_deg: 0.52");
  folder.write("req.yaml", requirements);
  const std::string rig = folder.write("rig.yaml", kRig);
  const CliResult result = run_cli({"metrics", rig});
  INFO(result.out << result.err);
  CHECK(result.out.find(folder.path() +
                        "/req.yaml:" + std::to_string(line_of(requirements, "from_deg: -0.52")) +
                        ":") != std::string::npos);
  CHECK(result.out.find("looks like radians") != std::string::npos);
  CHECK(result.out.find("-29.79") != std::string::npos);  // -0.52 rad in degrees
}

TEST_CASE(
    "a URDF origin in degrees is refused at its line; near-miss links and sensors are "
    "named") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  // A joint turned "90" about z: 90 rad is 14 turns and a quarter; 90 deg was meant.
  const std::string urdf =
      "<robot name=\"r\">\n  <link name=\"base_footprint\"/>\n"
      "  <link name=\"cam_link\"/>\n"
      "  <joint name=\"cam_joint\" type=\"fixed\">\n"
      "    <parent link=\"base_footprint\"/><child link=\"cam_link\"/>\n"
      "    <origin xyz=\"0.41 0 0.5\" rpy=\"0 0 90\"/>\n  </joint>\n"
      "</robot>\n";
  folder.write("r.urdf", urdf);
  const std::string with_urdf = input_replaced(kRig, "distance_of_interest: 3.0",
                                               "urdf: {file: r.urdf}\ndistance_of_interest: 3.0");
  const CliResult degrees = run_cli({"metrics", folder.write("deg.yaml", with_urdf)});
  INFO(degrees.out << degrees.err);
  CHECK(degrees.exit_code == 2);
  CHECK(degrees.err.find(folder.path() + "/r.urdf:6:") != std::string::npos);
  CHECK(degrees.err.find("looks like degrees") != std::string::npos);
  // The same joint in radians; a mount naming the link without its suffix is pointed at it.
  folder.write("r.urdf", input_replaced(urdf, "rpy=\"0 0 90\"", "rpy=\"0 0 1.5707963267948966\""));
  const CliResult near_link = run_cli(
      {"metrics",
       folder.write("near.yaml",
                    input_replaced(with_urdf, "pose: {xyz: [0.41, 0.0, 0.5], rpy_deg: [0, 20, 0]}",
                                   "pose: {urdf_link: cam}"))});
  CHECK(near_link.exit_code == 2);
  CHECK(near_link.err.find("no link 'cam' in the URDF (did you mean 'cam_link'?)") !=
        std::string::npos);
  // A sensor id with a letter doubled.
  const CliResult near_sensor =
      run_cli({"metrics",
               folder.write("sensor.yaml", input_replaced(kRig, "sensor: spin", "sensor: spinn"))});
  CHECK(near_sensor.exit_code == 2);
  CHECK(near_sensor.err.find("unknown sensor 'spinn'") != std::string::npos);
  CHECK(near_sensor.err.find("(did you mean 'spin'?)") != std::string::npos);
}

// A typo in a variable the description is asked to read (issue 30: HUSKY_LASER_3D_ENABLE):
// the Jackal's xacro reads JACKAL_LASER_3D, never JACKAL_LASER_3D_ENABLE.
TEST_CASE("an env variable the description never reads is a warning naming it") {
  TempFolder folder;
  const std::string rig =
      "name: Jackal\nsensor_library: " + source_path("sensors.yaml") + "\nrobot:\n  description: " +
      source_path("rigs/robots/jackal_description/urdf/jackal.urdf.xacro") +
      "\n  env: {JACKAL_LASER: 1, JACKAL_LASER_3D_ENABLE: 1}\n  package_paths: [" +
      source_path("rigs/robots") +
      "]\n  base_link: base_link\n  base_link_height: 0.0655\narea_height: 0.25\n"
      "distance_of_interest: 3.0\nmounts:\n  - {id: front_laser, sensor: sick_lms100, "
      "mode: res_0.5deg_25hz, pose: {urdf_link: front_laser}}\n";
  const CliResult result = run_cli({"metrics", folder.write("jackal.yaml", rig)});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 0);
  CHECK(result.out.find("warning: robot.env.JACKAL_LASER_3D_ENABLE: is never read") !=
        std::string::npos);
  CHECK(result.out.find("robot.env.JACKAL_LASER:") == std::string::npos);
}

// Two package_paths folders holding the same package: the first wins, as ROS would, but the
// rig's author hears about the other (issue 30).
TEST_CASE("a package found in two package_paths folders is a warning naming both") {
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  folder.write("req.yaml", kRequirements);
  const std::string package = "<package format=\"3\"><name>tiny</name></package>\n";
  std::filesystem::create_directories(folder.path() + "/first/tiny/urdf");
  std::filesystem::create_directories(folder.path() + "/second/tiny_copy/urdf");
  folder.write("first/tiny/package.xml", package);
  folder.write("second/tiny_copy/package.xml", package);
  const std::string part =
      "<?xml version=\"1.0\"?>\n<robot xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
      "  <link name=\"cam_link\"/>\n  <joint name=\"cam_joint\" type=\"fixed\">\n"
      "    <parent link=\"base_footprint\"/><child link=\"cam_link\"/>\n"
      "    <origin xyz=\"0.41 0 0.5\" rpy=\"0 0 0\"/>\n  </joint>\n</robot>\n";
  folder.write("first/tiny/urdf/part.xacro", part);
  folder.write("second/tiny_copy/urdf/part.xacro", part);
  folder.write(
      "robot.urdf.xacro",
      "<?xml version=\"1.0\"?>\n<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
      "  <link name=\"base_footprint\"/>\n"
      "  <xacro:include filename=\"$(find tiny)/urdf/part.xacro\"/>\n</robot>\n");
  const std::string rig = input_replaced(
      kRig, "distance_of_interest: 3.0",
      "robot: {description: robot.urdf.xacro, package_paths: [first, second], expander: builtin}\n"
      "distance_of_interest: 3.0");
  const CliResult result = run_cli({"metrics", folder.write("rig.yaml", rig)});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 0);
  CHECK(result.out.find("warning: robot.package_paths: package 'tiny' is in " + folder.path() +
                        "/first/tiny and in " + folder.path() + "/second/tiny_copy") !=
        std::string::npos);
}
