// Scene files: placement of static meshes, waypoint and ellipse motion at hand-computed
// times, the bundled lab, and located errors for bad scene files.
#include "rigdesign/io/scene/scene_file_loader.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <numbers>

#include "rigdesign/model/input_error.hpp"
#include "support/box_mesh.hpp"
#include "support/cli_runner.hpp"
#include "support/input_errors.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// The unit cube [0, 1]^3 as 6 quads: area 6.
const std::string kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 1 5 8 4\nf 2 3 7 6\n";

// Heading [deg] of a pose's x axis about +z.
double yaw_deg(const model::Pose3& T) {
  const model::Vec3 x_axis = T.linear().col(0);
  return std::atan2(x_axis.y(), x_axis.x()) * 180.0 / std::numbers::pi;
}

void check_position(const model::Pose3& T, double x, double y, double z) {
  CHECK(T.translation().x() == Approx(x).margin(1e-12));
  CHECK(T.translation().y() == Approx(y).margin(1e-12));
  CHECK(T.translation().z() == Approx(z).margin(1e-12));
}

// A scene file with the cube mesh beside it; `moving` is the body of one moving object.
std::string scene_with_moving(const TempFolder& folder, const std::string& moving) {
  folder.write("cube.obj", kCubeObj);
  return folder.write("scene.yaml",
                      "name: test\nmoving:\n  - name: box\n    mesh: cube.obj\n" + moving);
}

}  // namespace

TEST_CASE("static meshes are scaled, then posed, into the world frame", "[mesh_scene]") {
  TempFolder folder;
  folder.write("cube.obj", kCubeObj);
  const std::string path = folder.write("scene.yaml", R"(name: placed
robot_start: {xyz: [1, 2, 0], yaw_deg: 90}
static:
  - {name: big, mesh: cube.obj, pose: {xyz: [1, 2, 0], rpy_deg: [0, 0, 90]}, scale: 2}
  - {name: plain, mesh: cube.obj}
)");
  const model::Scene scene = io::load_scene_file(path);
  CHECK(scene.name == "placed");
  REQUIRE(scene.objects.size() == 2);
  CHECK(scene.moving.empty());
  // (1, 0, 0) scaled to (2, 0, 0), turned 90 deg left to (0, 2, 0), moved by (1, 2, 0).
  const model::TriangleMesh& big = scene.objects[0].mesh;
  CHECK(scene.objects[0].name == "big");
  CHECK((big.vertices[1] - model::Vec3(1, 4, 0)).norm() < 1e-12);
  CHECK(test::surface_area(big) == Approx(24.0));  // 6 faces of 2 x 2 m
  CHECK(test::surface_area(scene.objects[1].mesh) == Approx(6.0));
  check_position(scene.T_world_robot, 1, 2, 0);
  CHECK(yaw_deg(scene.T_world_robot) == Approx(90));
}

TEST_CASE("waypoints are interpolated linearly, yaw along the shorter arc", "[mesh_scene]") {
  TempFolder folder;
  const std::string motion = R"(    pose: {xyz: [0, 0, 0.5]}
    trajectory:
      loop: LOOP
      waypoints:
        - {t: 0, xyz: [0, 0, 0], yaw_deg: 170}
        - {t: 10, xyz: [2, 4, 0], yaw_deg: -170}
)";
  SECTION("clamped") {
    std::string text = motion;
    text.replace(text.find("LOOP"), 4, "false");
    const model::Scene scene = io::load_scene_file(scene_with_moving(folder, text));
    REQUIRE(scene.moving.size() == 1);
    const model::MovingObject& box = scene.moving[0];
    // The mesh is lifted by its pose in the object frame: vertex (0, 0, 0) at z = 0.5.
    CHECK((box.mesh.vertices[0] - model::Vec3(0, 0, 0.5)).norm() < 1e-12);
    // Midway: half of (2, 4, 0); yaw 170 -> -170 is 20 deg through 180, so 180 midway.
    const model::Pose3 middle = box.T_world_object(5.0);
    check_position(middle, 1, 2, 0);
    CHECK((middle.linear() * model::Vec3::UnitX() - model::Vec3(-1, 0, 0)).norm() < 1e-12);
    // A quarter of the way: 170 + 5 = 175 deg.
    CHECK(yaw_deg(box.T_world_object(2.5)) == Approx(175));
    check_position(box.T_world_object(2.5), 0.5, 1, 0);
    // Three quarters: 170 + 15 = 185 deg = -175 deg.
    CHECK(yaw_deg(box.T_world_object(7.5)) == Approx(-175));
    // Outside [0, 10] the ends hold.
    check_position(box.T_world_object(-3), 0, 0, 0);
    check_position(box.T_world_object(25), 2, 4, 0);
    CHECK(yaw_deg(box.T_world_object(25)) == Approx(-170));
  }
  SECTION("looped with period t_last - t_first = 10 s") {
    std::string text = motion;
    text.replace(text.find("LOOP"), 4, "true");
    const model::Scene scene = io::load_scene_file(scene_with_moving(folder, text));
    REQUIRE(scene.moving.size() == 1);
    check_position(scene.moving[0].T_world_object(12.5), 0.5, 1, 0);
    check_position(scene.moving[0].T_world_object(-2.5), 1.5, 3, 0);  // as t = 7.5
  }
}

TEST_CASE("a single waypoint holds its pose at every time", "[mesh_scene]") {
  TempFolder folder;
  const model::Scene scene = io::load_scene_file(scene_with_moving(
      folder, "    trajectory: {waypoints: [{t: 3, xyz: [1, 1, 0], yaw_deg: -45}]}\n"));
  REQUIRE(scene.moving.size() == 1);
  for (double t : {-10.0, 3.0, 100.0}) {
    check_position(scene.moving[0].T_world_object(t), 1, 1, 0);
    CHECK(yaw_deg(scene.moving[0].T_world_object(t)) == Approx(-45));
  }
}

TEST_CASE("an ellipse walk is at the top of the ellipse a quarter period in", "[mesh_scene]") {
  TempFolder folder;
  const std::string text =
      "    ellipse: {centre: [1, -1], semi_axes: [2, 1], period: 48, face_travel: FACE}\n";
  SECTION("facing the way it walks") {
    std::string facing = text;
    facing.replace(facing.find("FACE"), 4, "true");
    const model::Scene scene = io::load_scene_file(scene_with_moving(folder, facing));
    REQUIRE(scene.moving.size() == 1);
    const auto& T = scene.moving[0].T_world_object;
    // t = 0: at (1 + 2, -1), walking counter-clockwise, so along +y.
    check_position(T(0), 3, -1, 0);
    CHECK(yaw_deg(T(0)) == Approx(90));
    // t = period / 4 = 12 s: angle 90 deg, at (1, -1 + 1), walking along -x.
    check_position(T(12), 1, 0, 0);
    CHECK((T(12).linear() * model::Vec3::UnitX() - model::Vec3(-1, 0, 0)).norm() < 1e-12);
    // One lap later, the same place.
    CHECK((T(60).translation() - T(12).translation()).norm() < 1e-12);
  }
  SECTION("keeping its heading") {
    std::string fixed = text;
    fixed.replace(fixed.find("FACE"), 4, "false");
    const model::Scene scene = io::load_scene_file(scene_with_moving(folder, fixed));
    REQUIRE(scene.moving.size() == 1);
    check_position(scene.moving[0].T_world_object(12), 1, 0, 0);
    CHECK(scene.moving[0].T_world_object(12).linear().isIdentity(1e-12));
  }
}

TEST_CASE("the bundled lab scene loads with its room, table and two walkers", "[mesh_scene]") {
  const model::Scene scene = io::load_scene_file(source_path("rigs/scenes/lab/lab.yaml"));
  CHECK(scene.name == "lab");
  REQUIRE(scene.objects.size() == 2);
  REQUIRE(scene.moving.size() == 2);
  CHECK(scene.objects[0].name == "room");
  CHECK(scene.objects[1].name == "table");
  // Room: 6 x 4 m floor and walls 2.5 m high around 20 m of perimeter, no ceiling.
  CHECK(test::surface_area(scene.objects[0].mesh) == Approx(6 * 4 + 20 * 2.5));
  // Every part of the scene stays inside the room at any time of the loops.
  for (double t = 0; t < 30; t += 0.5) {
    model::Vec2 farthest = model::Vec2::Zero();
    for (const model::Vec3& v : scene.at(t).vertices) {
      farthest = farthest.cwiseMax(v.head<2>().cwiseAbs());
    }
    INFO("t = " << t);
    CHECK(farthest.x() <= 3.0 + 1e-9);
    CHECK(farthest.y() <= 2.0 + 1e-9);
  }
}

TEST_CASE("bad scene files name the file, line, column and field", "[mesh_scene]") {
  TempFolder folder;
  const std::string yaml = folder.path() + "/scene.yaml";
  const auto error_with = [&](const std::string& moving) {
    return test::input_error_of([&] { io::load_scene_file(scene_with_moving(folder, moving)); });
  };
  SECTION("waypoint times not increasing") {
    const std::string message = error_with(R"(    trajectory:
      waypoints:
        - {t: 0, xyz: [0, 0, 0]}
        - {t: 0, xyz: [1, 0, 0]}
)");
    CHECK(message.find(yaml + ":8:15: moving[0].trajectory.waypoints[1].t: is not after") == 0);
  }
  SECTION("no waypoints") {
    const std::string message = error_with("    trajectory: {loop: true, waypoints: []}\n");
    CHECK(message.find(yaml + ":5:41: moving[0].trajectory.waypoints: is empty") == 0);
  }
  SECTION("a semi-axis that is not positive") {
    const std::string message = error_with("    ellipse: {semi_axes: [2, 0], period: 10}\n");
    CHECK(message.find(yaml + ":5:26: moving[0].ellipse.semi_axes: has a semi-axis <= 0") == 0);
  }
  SECTION("a period that is not positive") {
    const std::string message = error_with("    ellipse: {semi_axes: [2, 1], period: -4}\n");
    CHECK(message.find(yaml + ":5:42: moving[0].ellipse.period: must be > 0") == 0);
  }
  SECTION("both or neither motion") {
    CHECK(error_with("    scale: 2\n").find(yaml + ":3:5: moving[0].trajectory: missing") == 0);
  }
  SECTION("a mesh file that does not exist") {
    const std::string path =
        folder.write("scene.yaml", "name: t\nstatic:\n  - name: room\n    mesh: rooms/room.obj\n");
    const std::string message = test::input_error_of([&] { io::load_scene_file(path); });
    CHECK(message.find(yaml + ":4:11: static[0].mesh: file '") == 0);
    CHECK(message.find("does not exist") != std::string::npos);
  }
  SECTION("a mesh file of an unknown format") {
    folder.write("room.stl", "solid\n");
    const std::string path =
        folder.write("scene.yaml", "name: t\nstatic:\n  - {name: room, mesh: room.stl}\n");
    const std::string message = test::input_error_of([&] { io::load_scene_file(path); });
    CHECK(message.find(yaml + ":3:24: static[0].mesh: 'room.stl' is not a mesh file") == 0);
  }
  SECTION("a problem inside the mesh names the mesh file's line") {
    folder.write("room.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    const std::string path =
        folder.write("scene.yaml", "name: t\nstatic:\n  - {name: room, mesh: room.obj}\n");
    const std::string message = test::input_error_of([&] { io::load_scene_file(path); });
    CHECK(message.find(folder.path() + "/room.obj:4:7: f: refers to vertex 4") == 0);
  }
  SECTION("duplicate names and unknown fields are all reported") {
    folder.write("cube.obj", kCubeObj);
    const std::string path = folder.write("scene.yaml", R"(name: t
static:
  - {name: a, mesh: cube.obj}
  - {name: a, mesh: cube.obj, colour: red}
)");
    const std::string message = test::input_error_of([&] { io::load_scene_file(path); });
    CHECK(message.find(yaml + ":4:12: static[1].name: duplicate object name 'a'") !=
          std::string::npos);
    CHECK(message.find(yaml + ":4:31: static[1].colour: unknown field") != std::string::npos);
  }
  SECTION("a scene without objects") {
    const std::string path = folder.write("scene.yaml", "name: t\nstatic: []\n");
    const std::string message = test::input_error_of([&] { io::load_scene_file(path); });
    CHECK(message.find(yaml + ":2:9: static: the scene has no objects") == 0);
  }
}
