// Mesh files: a unit cube in every format and layout (ascii and binary PLY written byte by
// byte here, OBJ with every corner form and negative indices, OFF with comments), checked by
// triangle count, area and enclosed volume computed here; and located errors for bad input.
#include "rigdesign/io/mesh/mesh_loader.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <functional>

#include "rigdesign/model/input_error.hpp"
#include "support/box_mesh.hpp"
#include "support/byte_text.hpp"
#include "support/input_errors.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

const model::Vec3& corner(const model::TriangleMesh& mesh, int index) {
  return mesh.vertices.at(static_cast<std::size_t>(index));
}

// Divergence theorem: positive when every face winds counter-clockwise seen from outside.
double signed_volume(const model::TriangleMesh& mesh) {
  double six_volume = 0;
  for (const auto& t : mesh.triangles) {
    six_volume += corner(mesh, t[0]).dot(corner(mesh, t[1]).cross(corner(mesh, t[2])));
  }
  return six_volume / 6;
}

// The unit cube [0, 1]^3: 8 corners and 6 quads wound counter-clockwise seen from outside.
// A quad splits into 2 triangles, so 12 triangles, area 6, volume 1.
const char* kCubeVertices[8] = {"0 0 0", "1 0 0", "1 1 0", "0 1 0",
                                "0 0 1", "1 0 1", "1 1 1", "0 1 1"};
const int kCubeQuads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};

void check_unit_cube(const model::TriangleMesh& mesh) {
  CHECK(mesh.vertices.size() == 8);
  CHECK(mesh.triangles.size() == 12);
  CHECK(test::surface_area(mesh) == Approx(6.0));
  CHECK(signed_volume(mesh) == Approx(1.0));
}

// The InputError message `load` throws, or "" when it throws none.
std::string load_error(const TempFolder& folder, const std::string& name,
                       const std::string& contents) {
  const std::string path = folder.write(name, contents);
  return test::input_error_of([&] { io::load_mesh(path); });
}

std::string cube_ply_ascii_header() {
  return "ply\nformat ascii 1.0\ncomment unit cube\nelement vertex 8\nproperty float x\n"
         "property float y\nproperty float z\nproperty uchar red\nelement face 6\n"
         "property list uchar int vertex_indices\nproperty int flags\nelement edge 1\n"
         "property int vertex1\nproperty int vertex2\nend_header\n";
}

std::string cube_ply_ascii() {
  std::string text = cube_ply_ascii_header();
  for (const char* vertex : kCubeVertices) text += std::string(vertex) + " 255\n";
  for (const auto& quad : kCubeQuads) {
    text += "4";
    for (int index : quad) text += " " + std::to_string(index);
    text += " 7\n";
  }
  return text + "0 1\n";
}

// Doubles for x y z with a float between y and z, an element before the vertices, faces as
// `list uint uint vertex_index` (the other name writers use).
std::string cube_ply_binary(int faces_to_write = 6) {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement material 1\nproperty short id\n"
      "element vertex 8\nproperty double x\nproperty double y\nproperty float confidence\n"
      "property double z\nelement face 6\nproperty list uint uint vertex_index\nend_header\n";
  bytes += bytes_of(static_cast<std::int16_t>(3));
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& c : corners) {
    bytes += bytes_of(c[0]) + bytes_of(c[1]) + bytes_of(0.5f) + bytes_of(c[2]);
  }
  for (int f = 0; f < faces_to_write; ++f) {
    bytes += bytes_of(std::uint32_t{4});
    for (int index : kCubeQuads[f]) bytes += bytes_of(static_cast<std::uint32_t>(index));
  }
  return bytes;
}

std::string cube_obj() {
  std::string text = "# unit cube\nmtllib cube.mtl\no cube\n";
  for (const char* vertex : kCubeVertices) text += "v " + std::string(vertex) + "\n";
  text += "vt 0 0\nvn 0 0 1\ns off\n";
  // One corner form per face, all naming vertex i.
  const char* forms[6] = {"{}", "{}/1", "{}/1/1", "{}//1", "{}/1", "{}"};
  for (int f = 0; f < 6; ++f) {
    text += "f";
    for (int index : kCubeQuads[f]) {
      std::string corner_text = forms[f];
      corner_text.replace(0, 2, std::to_string(index + 1));
      text += " " + corner_text;
    }
    text += "\n";
  }
  return text;
}

std::string cube_off() {
  std::string text = "OFF\n# unit cube, counts on their own line\n\n8 6 12\n";
  for (const char* vertex : kCubeVertices) text += std::string(vertex) + "  # corner\n";
  for (const auto& quad : kCubeQuads) {
    text += "4";
    for (int index : quad) text += " " + std::to_string(index);
    text += "\n";
  }
  return text;
}

}  // namespace

TEST_CASE("a unit cube reads as 12 triangles of area 6 from every format", "[mesh_scene]") {
  TempFolder folder;
  SECTION("PLY ascii with extra properties and elements") {
    check_unit_cube(io::load_mesh(folder.write("cube.ply", cube_ply_ascii())));
  }
  SECTION("PLY binary little endian, doubles, an element before the vertices") {
    check_unit_cube(io::load_mesh(folder.write("cube.PLY", cube_ply_binary())));
  }
  SECTION("OBJ with i, i/j, i/j/k and i//k corners") {
    check_unit_cube(io::load_mesh(folder.write("cube.obj", cube_obj())));
  }
  SECTION("OFF with comments and counts on their own line") {
    check_unit_cube(io::load_mesh(folder.write("cube.off", cube_off())));
  }
  SECTION("OFF with the counts on the keyword's line and triangles") {
    std::string text = "OFF 8 12 0\n";
    for (const char* vertex : kCubeVertices) text += std::string(vertex) + "\n";
    for (const auto& q : kCubeQuads) {
      text += "3 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
              std::to_string(q[2]) + "\n3 " + std::to_string(q[0]) + " " + std::to_string(q[2]) +
              " " + std::to_string(q[3]) + " 255 0 0\n";  // a face colour after the indices
    }
    check_unit_cube(io::load_mesh(folder.write("cube.off", text)));
  }
}

TEST_CASE("polygons are split into a fan around their first corner", "[mesh_scene]") {
  TempFolder folder;
  // A convex pentagon's corners in order; the fan is (0,1,2), (0,2,3), (0,3,4).
  const model::TriangleMesh pentagon = io::load_mesh(
      folder.write("pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n"));
  REQUIRE(pentagon.triangles.size() == 3);
  CHECK(pentagon.triangles[0] == std::array<int, 3>{0, 1, 2});
  CHECK(pentagon.triangles[1] == std::array<int, 3>{0, 2, 3});
  CHECK(pentagon.triangles[2] == std::array<int, 3>{0, 3, 4});
  // Shoelace area of the (convex) pentagon: (0 + 2 + 5 + 3 + 0) / 2 = 5 m^2.
  CHECK(test::surface_area(pentagon) == Approx(5.0));
}

TEST_CASE("negative OBJ indices count back from the latest vertex", "[mesh_scene]") {
  TempFolder folder;
  // Each quad right after its own four corners, named -4 -3 -2 -1.
  std::string text;
  for (const auto& quad : kCubeQuads) {
    for (int index : quad) text += "v " + std::string(kCubeVertices[index]) + "\n";
    text += "f -4 -3 -2/1 -1//1\n";
  }
  const model::TriangleMesh mesh = io::load_mesh(folder.write("cube.obj", text));
  CHECK(mesh.vertices.size() == 24);
  CHECK(mesh.triangles.size() == 12);
  CHECK(test::surface_area(mesh) == Approx(6.0));
  CHECK(signed_volume(mesh) == Approx(1.0));
  CHECK(mesh.triangles[2] == std::array<int, 3>{4, 5, 6});  // second quad: vertices 5..8
}

TEST_CASE("bad mesh files name the file, line, column and field", "[mesh_scene]") {
  TempFolder folder;
  const std::string dir = folder.path() + "/";
  SECTION("unknown extension") {
    const std::string message = load_error(folder, "cube.stl", "solid cube\n");
    CHECK(message.find(dir + "cube.stl: file: unknown mesh format '.stl'") == 0);
  }
  SECTION("OBJ: a coordinate that is not a number") {
    const std::string message = load_error(folder, "bad.obj", "# c\nv 0 0 0\nv 1 abc 0\n");
    CHECK(message.find(dir + "bad.obj:3:5: v: 'abc' is not a finite number") == 0);
  }
  SECTION("OBJ: an index past the last vertex") {
    const std::string message =
        load_error(folder, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9/1\n");
    CHECK(message.find(dir + "bad.obj:5:7: f: refers to vertex 9; the file has 3 vertices") == 0);
  }
  SECTION("OBJ: a negative index before the first vertex") {
    const std::string message = load_error(folder, "bad.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\n");
    CHECK(message.find(dir + "bad.obj:3:9: f: relative index -3") == 0);
  }
  SECTION("OBJ: a face with two corners") {
    const std::string message = load_error(folder, "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
    CHECK(message.find(dir + "bad.obj:3:1: f: has 2 corner(s)") == 0);
  }
  SECTION("OBJ: vertices only, no faces") {
    const std::string message = load_error(folder, "points.obj", "v 0 0 0\nv 1 0 0\n");
    CHECK(message.find(dir + "points.obj: faces: the mesh has no faces") == 0);
  }
  SECTION("OFF: truncated vertex list") {
    std::string text = cube_off();
    text = text.substr(0, text.find("1 0 1"));  // 5 of 8 vertices, on lines 5 to 9
    const std::string message = load_error(folder, "bad.off", text);
    CHECK(message.find(dir + "bad.off:9:1: vertex[5]: the file ends before vertex 5 of 8") == 0);
  }
  SECTION("OFF: a face index out of range") {
    const std::string message =
        load_error(folder, "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
    CHECK(message.find(dir + "bad.off:6:7: face[0]: refers to vertex 3; the file has 3") == 0);
  }
  SECTION("OFF: counts that are not numbers") {
    const std::string message = load_error(folder, "bad.off", "OFF\n8 six 0\n");
    CHECK(message.find(dir + "bad.off:2:3: counts: 'six' is not a count") == 0);
  }
  SECTION("PLY ascii: a coordinate that is not a number") {
    std::string text = cube_ply_ascii();
    text.replace(text.find("1 0 0 255"), 9, "1 x 0 255");  // vertex 1, line 17
    const std::string message = load_error(folder, "bad.ply", text);
    CHECK(message.find(dir + "bad.ply:17:3: vertex[1].y: 'x' is not a number") == 0);
  }
  SECTION("PLY ascii: a face index out of range") {
    std::string text = cube_ply_ascii();
    text.replace(text.find("4 4 5 6 7 7"), 11, "4 4 5 6 8 7");  // face 1, line 25
    const std::string message = load_error(folder, "bad.ply", text);
    CHECK(message.find(dir + "bad.ply:25:9: face[1].vertex_indices: refers to vertex 8") == 0);
  }
  SECTION("PLY ascii: fewer faces than declared") {
    std::string text = cube_ply_ascii_header();
    for (const char* vertex : kCubeVertices) text += std::string(vertex) + " 255\n";
    text += "3 0 1 2 0\n";
    const std::string message = load_error(folder, "bad.ply", text);
    CHECK(message.find(dir + "bad.ply:24:1: face[1]: the file ends after 1 of 6 face records") ==
          0);
  }
  SECTION("PLY binary: truncated face list") {
    const std::string message = load_error(folder, "bad.ply", cube_ply_binary(5));
    CHECK(message.find(dir + "bad.ply: face[5]: the binary body ends inside face record 5") == 0);
    CHECK(message.find("byte offset") != std::string::npos);
  }
  SECTION("PLY binary: a face index out of range") {
    std::string bytes = cube_ply_binary();
    const std::size_t body = bytes.find("end_header\n") + 11;
    // material (2 bytes), 8 vertices of 28 bytes, 3 faces of 20 bytes, the count, 2 indices.
    const std::size_t at = body + 2 + 8 * 28 + 3 * 20 + 4 + 2 * 4;
    bytes.replace(at, 4, bytes_of(std::uint32_t{42}));
    const std::string message = load_error(folder, "bad.ply", bytes);
    CHECK(message.find(dir +
                       "bad.ply: face[3].vertex_index: refers to vertex 42; the file has 8") == 0);
    CHECK(message.find("record 3 of its element, byte offset " + std::to_string(at)) !=
          std::string::npos);
  }
  SECTION("PLY without faces is a cloud, not a mesh") {
    const std::string message =
        load_error(folder, "cloud.ply",
                   "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                   "property float z\nend_header\n0 0 0\n");
    CHECK(message.find(dir + "cloud.ply:7:1: element face: the header declares no face element") ==
          0);
  }
  SECTION("a missing file") {
    const std::string message = test::input_error_of([&] { io::load_mesh(dir + "absent.obj"); });
    CHECK(message.find(dir + "absent.obj: file: cannot be opened") == 0);
  }
}
