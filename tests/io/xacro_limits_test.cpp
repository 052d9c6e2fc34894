// Descriptions that would run the built-in expander out of stack, memory or time (the
// reliability reproducers 01-05), and the external xacro's process: what of a rig file may
// reach it and where its output goes (17, 18). Each hostile description is written here
// from its definition, not from rigdesign's output.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "support/input_errors.hpp"
#include "support/path_guard.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

const std::string kHead =
    "<?xml version=\"1.0\"?>\n<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";
const std::string kLinks =
    "<link name=\"base_link\"><collision><geometry><box size=\"0.4 0.4 0.3\"/></geometry>"
    "</collision></link>\n<link name=\"laser\"/>\n"
    "<joint name=\"j\" type=\"fixed\"><parent link=\"base_link\"/><child link=\"laser\"/>"
    "<origin xyz=\"0 0 ${z}\"/></joint>\n";

std::string plain_links() {
  std::string links = kLinks;
  links.replace(links.find("${z}"), 4, "0.4");
  return links;
}

io::RobotDescriptionRequest builtin(const std::string& path) {
  io::RobotDescriptionRequest request;
  request.path = path;
  request.expander = io::RobotDescriptionRequest::Expander::builtin;
  return request;
}

std::string load_error(const std::string& path) {
  return input_error_of([&] { io::load_robot_description(builtin(path)); });
}

// A chain z = q0, q0 = ${q1}, ..., q(n-1) = ${qn}, qn = 0.4.
std::string property_chain(int n) {
  std::ostringstream text;
  text << kHead << "<xacro:property name=\"z\" value=\"${q0}\"/>\n";
  for (int k = 0; k < n; ++k) {
    text << "<xacro:property name=\"q" << k << "\" value=\"${q" << k + 1 << "}\"/>\n";
  }
  text << "<xacro:property name=\"q" << n << "\" value=\"0.4\"/>\n" << kLinks << "</robot>\n";
  return text.str();
}

}  // namespace

TEST_CASE("xacro expansion is bounded: depth, size, calls and includes, at the line") {
  TempFolder folder;
  SECTION("a block property that inserts itself (01)") {
    const std::string path = folder.write(
        "r.urdf.xacro", kHead + "<xacro:property name=\"z\" value=\"0.4\"/>\n" +
                            "<xacro:property name=\"blk\"><xacro:insert_block name=\"blk\"/>"
                            "</xacro:property>\n" +
                            kLinks + "<xacro:insert_block name=\"blk\"/>\n</robot>\n");
    const std::string message = load_error(path);
    CHECK(message.find(path + ":4:") == 0);  // the insert_block inside the property
    CHECK(message.find("more than 100 nested") != std::string::npos);
  }
  SECTION("a chain of 5000 lazy properties (02) stops; one of 60 expands") {
    CHECK(load_error(folder.write("long.urdf.xacro", property_chain(5000)))
              .find("more than 100 nested") != std::string::npos);
    const model::RobotDescription robot =
        io::load_robot_description(builtin(folder.write("short.urdf.xacro", property_chain(60))));
    CHECK(robot.T_base("base_link", "laser").value().translation().z() == 0.4);
  }
  SECTION("a property doubling 40 times (03): the 1 MiB value limit, where it is crossed") {
    std::ostringstream text;
    text << kHead << "<xacro:property name=\"z\" value=\"0.4\"/>\n"
         << "<xacro:property name=\"p0\" value=\"aaaaaaaaaaaaaaaa\"/>\n";  // line 4
    for (int k = 1; k <= 40; ++k) {
      text << "<xacro:property name=\"p" << k << "\" value=\"${p" << k - 1 << "}${p" << k - 1
           << "}\"/>\n";  // line 4 + k
    }
    text << kLinks << "<link name=\"x\"><visual><material name=\"${p40}\"/></visual></link>\n"
         << "</robot>\n";
    const std::string path = folder.write("r.urdf.xacro", text.str());
    const std::string message = load_error(path);
    // 16 * 2^16 bytes = 1 MiB is p16's value; p17 is the first above it (line 21).
    CHECK(message.find(path + ":21:") == 0);
    CHECK(message.find("more than 1 MiB") != std::string::npos);
  }
  SECTION("a macro calling the previous one twice, 30 levels (04): 2^30 calls refused") {
    std::ostringstream text;
    text << kHead << "<xacro:property name=\"z\" value=\"0.4\"/>\n"
         << "<xacro:macro name=\"m0\" params=\"\"><xacro:property name=\"x\" value=\"1\"/>"
         << "</xacro:macro>\n";
    for (int k = 1; k <= 30; ++k) {
      text << "<xacro:macro name=\"m" << k << "\" params=\"\"><xacro:m" << k - 1 << "/><xacro:m"
           << k - 1 << "/></xacro:macro>\n";
    }
    text << kLinks << "<xacro:m30/>\n</robot>\n";
    CHECK(
        load_error(folder.write("r.urdf.xacro", text.str())).find("more than 200000 macro calls") !=
        std::string::npos);
  }
  SECTION("macros emitting links, doubling 20 levels: the element limit") {
    std::ostringstream text;
    text << kHead << "<xacro:property name=\"z\" value=\"0.4\"/>\n"
         << "<xacro:macro name=\"m0\" params=\"\"><link name=\"a\"/><link name=\"b\"/><link "
            "name=\"c\"/>"
         << "<link name=\"d\"/>"
         << "</xacro:macro>\n";
    for (int k = 1; k <= 20; ++k) {
      text << "<xacro:macro name=\"m" << k << "\" params=\"\"><xacro:m" << k - 1 << "/><xacro:m"
           << k - 1 << "/></xacro:macro>\n";
    }
    text << kLinks << "<xacro:m20/>\n</robot>\n";
    CHECK(load_error(folder.write("r.urdf.xacro", text.str())).find("more than 200000 elements") !=
          std::string::npos);
  }
  SECTION("24 files each including the next twice (05): 2^24 includes refused") {
    folder.write("top.urdf.xacro", kHead + "<xacro:property name=\"z\" value=\"0.4\"/>\n" + kLinks +
                                       "<xacro:include filename=\"f1.xacro\"/></robot>\n");
    for (int k = 1; k < 24; ++k) {
      folder.write("f" + std::to_string(k) + ".xacro",
                   kHead + "<xacro:include filename=\"f" + std::to_string(k + 1) +
                       ".xacro\"/><xacro:include filename=\"f" + std::to_string(k + 1) +
                       ".xacro\"/></robot>\n");
    }
    folder.write("f24.xacro", kHead + "<xacro:property name=\"leaf\" value=\"1\"/></robot>\n");
    CHECK(load_error(folder.path() + "/top.urdf.xacro").find("more than 10000 includes") !=
          std::string::npos);
  }
}

TEST_CASE("the external xacro runs with a minimal environment and a private output file") {
  TempFolder folder;
  // A stand-in for ROS's xacro that records its environment beside the rig and prints the
  // description it is given.
  const std::string record = folder.path() + "/environment.txt";
  const std::string script =
      folder.write("bin/xacro", "#!/bin/sh\nenv > '" + record + "'\ncat \"$1\"\n");
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  const PathGuard path_guard(folder.path() + "/bin");
  const std::string description =
      folder.write("r.urdf.xacro", kHead + plain_links() + "</robot>\n");  // `cat` expands nothing
  const auto environment_of_run = [&](const std::map<std::string, std::string>& rig_env) {
    io::RobotDescriptionRequest request;
    request.path = description;
    request.environment = rig_env;
    io::load_robot_description(request);
    std::ifstream stream(record);
    std::stringstream text;
    text << stream.rdbuf();
    return "\n" + text.str();
  };
  SECTION("this process's other variables and a rig's PYTHONPATH never reach it") {
    ::setenv("RIGDESIGN_TEST_SECRET", "token", 1);
    const std::string seen = environment_of_run({{"JACKAL_LASER", "1"}, {"PYTHONPATH", "/x"}});
    ::unsetenv("RIGDESIGN_TEST_SECRET");
    CHECK(seen.find("\nJACKAL_LASER=1\n") != std::string::npos);
    CHECK(seen.find("\nPATH=" + folder.path() + "/bin:") != std::string::npos);
    CHECK(seen.find("RIGDESIGN_TEST_SECRET") == std::string::npos);
    CHECK(seen.find("PYTHONPATH=/x") == std::string::npos);
  }
  SECTION("a rig file naming PYTHONPATH, LD_PRELOAD or an option as an argument is refused") {
    const std::string rig_head =
        "name: r\nsensor_library: " + std::string(RIGDESIGN_SOURCE_DIR) +
        "/sensors.yaml\nrobot:\n  description: r.urdf.xacro\n  base_link: base_link\n";
    const std::string tail =
        "area_height: 0.5\ndistance_of_interest: 2.0\nmounts:\n"
        "  - {id: lidar, sensor: rplidar_a1m8, mode: 5_5hz, pose: {urdf_link: laser}}\n";
    const std::string python =
        folder.write("python.yaml", rig_head + "  env: {PYTHONPATH: /x}\n" + tail);
    CHECK(input_error_of([&] {
            io::load_rig(python);
          }).find(python + ":6:9: robot.env.PYTHONPATH") == 0);
    const std::string preload =
        folder.write("preload.yaml", rig_head + "  env: {ld_preload: /x.so}\n" + tail);
    CHECK(input_error_of([&] { io::load_rig(preload); }).find("robot.env.ld_preload") !=
          std::string::npos);
    const std::string option =
        folder.write("option.yaml", rig_head + "  args: {\"-o\": /tmp/x}\n" + tail);
    CHECK(input_error_of([&] { io::load_rig(option); }).find("robot.args.-o") != std::string::npos);
  }
  SECTION("a symlink planted at the old predictable path is left alone (18)") {
    const std::filesystem::path planted =
        std::filesystem::temp_directory_path() / ("rigdesign-xacro-" + std::to_string(::getpid()));
    std::filesystem::create_directories(planted);
    const std::string victim = folder.write("victim.txt", "precious data");
    std::filesystem::create_symlink(victim, planted / "out.urdf");
    environment_of_run({});
    std::filesystem::remove_all(planted);
    std::ifstream stream(victim);
    std::string first;
    std::getline(stream, first);
    CHECK(first == "precious data");
  }
}
