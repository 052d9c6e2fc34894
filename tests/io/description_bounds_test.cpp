// Robot descriptions that urdfdom accepts but rigdesign must not compute with (reliability
// reproducers 14 and 20): a zero scale, a joint at 1e300 m, a huge mesh file, a FIFO as a
// mesh; and a rig's base_link_height of 1e300 m. Each is refused at its line.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "support/input_errors.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// Line 3 holds the base link's collision, line 5 the joint.
std::string description(const std::string& collision, const std::string& joint_xyz) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n"
         "<link name=\"base_link\"><collision><geometry>" +
         collision +
         "</geometry></collision></link>\n<link name=\"laser\"/>\n"
         "<joint name=\"j\" type=\"fixed\"><parent link=\"base_link\"/><child link=\"laser\"/>"
         "<origin xyz=\"" +
         joint_xyz + "\"/></joint>\n</robot>\n";
}

std::string load_error(const TempFolder& folder, const std::string& text) {
  const std::string path = folder.write("r.urdf", text);
  io::RobotDescriptionRequest request;
  request.path = path;
  return input_error_of([&] { io::load_robot_description(request); });
}

const std::string kTriangle =
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
    "endloop\nendfacet\nendsolid t\n";

}  // namespace

TEST_CASE("degenerate geometry in a description is refused at its line (20)") {
  TempFolder folder;
  folder.write("t.stl", kTriangle);
  const std::string path = folder.path() + "/r.urdf";
  CHECK(load_error(folder, description("<box size=\"0.4 0.4 0.3\"/>", "0 0 0.4")).empty());
  CHECK(load_error(folder, description("<mesh filename=\"t.stl\" scale=\"0 0 0\"/>", "0 0 0.4"))
            .find(path + ":3:") == 0);
  CHECK(load_error(folder, description("<mesh filename=\"t.stl\" scale=\"0 0 0\"/>", "0 0 0.4"))
            .find("mesh.scale") != std::string::npos);
  // A mirrored mesh (negative factor) is what Gazebo and RViz draw: accepted.
  CHECK(load_error(folder, description("<mesh filename=\"t.stl\" scale=\"-1 1 1\"/>", "0 0 0.4"))
            .empty());
  CHECK(load_error(folder, description("<box size=\"0.4 0 0.3\"/>", "0 0 0.4")).find("box.size") !=
        std::string::npos);
  CHECK(load_error(folder, description("<sphere radius=\"0\"/>", "0 0 0.4")).find("sphere") !=
        std::string::npos);
  const std::string far =
      load_error(folder, description("<box size=\"0.4 0.4 0.3\"/>", "1e300 0 0.4"));
  CHECK(far.find(path + ":5:") == 0);
  CHECK(far.find("joint 'j' origin") != std::string::npos);
  CHECK(load_error(folder, description("<box size=\"0.4 0.4 0.3\"/>", "1.5e8 0 0.4"))
            .find("beyond +-1e8 m") != std::string::npos);
}

TEST_CASE("a mesh file too large to be a collision mesh, or not a file, is refused unread (14)") {
  TempFolder folder;
  // 65 MiB, sparse: refused by its size before any byte is read.
  const std::string big = folder.write("big.stl", "");
  std::filesystem::resize_file(big, (std::uintmax_t{65} << 20));
  CHECK(load_error(folder, description("<mesh filename=\"big.stl\"/>", "0 0 0.4"))
            .find("is 65 MiB") != std::string::npos);
  REQUIRE(::mkfifo((folder.path() + "/pipe.stl").c_str(), 0600) == 0);
  CHECK(load_error(folder, description("<mesh filename=\"pipe.stl\"/>", "0 0 0.4"))
            .find("not a regular file") != std::string::npos);
  REQUIRE(::mkfifo((folder.path() + "/pipe.urdf").c_str(), 0600) == 0);
  io::RobotDescriptionRequest request;
  request.path = folder.path() + "/pipe.urdf";
  CHECK(input_error_of([&] { io::load_robot_description(request); }).find("not a regular file") !=
        std::string::npos);
}

TEST_CASE("a rig's base_link_height beyond +-100 m is refused at its line (20)") {
  TempFolder folder;
  folder.write("r.urdf", description("<box size=\"0.4 0.4 0.3\"/>", "0 0 0.4"));
  const std::string rig = folder.write(
      "rig.yaml", "name: r\nsensor_library: " + std::string(RIGDESIGN_SOURCE_DIR) +
                      "/sensors.yaml\nrobot:\n  description: r.urdf\n  base_link: base_link\n"
                      "  base_link_height: 1e300\narea_height: 0.5\ndistance_of_interest: 2.0\n"
                      "mounts:\n  - {id: lidar, sensor: rplidar_a1m8, mode: 5_5hz, "
                      "pose: {urdf_link: laser}}\n");
  CHECK(input_error_of([&] { io::load_rig(rig); }).find(rig + ":6:21: robot.base_link_height") ==
        0);
}
