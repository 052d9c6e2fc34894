// The inside test on closed and open meshes (issue 52 item 1), against solid angles computed
// by hand from the rectangle formula Omega = 4 asin(a b / sqrt((a^2 + d^2)(b^2 + d^2))) (a
// 2a x 2b rectangle seen on its axis from distance d), not the triangle formula the code uses.
#include "rigdesign/geometry/winding_number.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

namespace rigdesign {
namespace {

// The unit cube [0, 1]^3, each face two triangles wound counter-clockwise seen from outside;
// `open_top` leaves out the face z = 1.
model::TriangleMesh unit_cube(bool open_top) {
  model::TriangleMesh cube;
  for (int i = 0; i < 8; ++i) cube.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::vector<std::array<int, 4>> faces = {
      {0, 2, 3, 1},  // z = 0, normal -z
      {4, 5, 7, 6},  // z = 1, normal +z
      {0, 1, 5, 4},  // y = 0, normal -y
      {2, 6, 7, 3},  // y = 1, normal +y
      {0, 4, 6, 2},  // x = 0, normal -x
      {1, 3, 7, 5},  // x = 1, normal +x
  };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (open_top && f == 1) continue;
    const std::array<int, 4>& q = faces[f];
    cube.triangles.push_back({q[0], q[1], q[2]});
    cube.triangles.push_back({q[0], q[2], q[3]});
  }
  return cube;
}

// Solid angle of a square of side `side` seen on its axis from `distance`, over 4 pi.
double square_share(double side, double distance) {
  const double h = side / 2;
  return 4 * std::asin(h * h / (h * h + distance * distance)) / (4 * std::numbers::pi);
}

TEST_CASE("winding number: 1 inside a closed cube, 0 outside, either orientation", "[geometry]") {
  const model::TriangleMesh cube = unit_cube(false);
  CHECK(geometry::winding_number(cube, {0.5, 0.5, 0.5}) == Approx(1.0).margin(1e-12));
  CHECK(geometry::winding_number(cube, {0.1, 0.8, 0.3}) == Approx(1.0).margin(1e-12));
  CHECK(geometry::winding_number(cube, {2.0, 0.5, 0.5}) == Approx(0.0).margin(1e-12));
  CHECK(geometry::inside_mesh(cube, {0.5, 0.5, 0.5}));
  CHECK_FALSE(geometry::inside_mesh(cube, {-0.01, 0.5, 0.5}));
  model::TriangleMesh flipped = cube;
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  CHECK(geometry::winding_number(flipped, {0.5, 0.5, 0.5}) == Approx(-1.0).margin(1e-12));
  CHECK(geometry::inside_mesh(flipped, {0.5, 0.5, 0.5}));
}

TEST_CASE("winding number on a box without a lid: the hole does not turn outside in",
          "[geometry]") {
  const model::TriangleMesh box = unit_cube(true);
  // From the centre each face is a sixth of the sphere (a square of side 1 at 0.5): 5/6.
  CHECK(square_share(1.0, 0.5) == Approx(1.0 / 6.0));
  CHECK(geometry::winding_number(box, {0.5, 0.5, 0.5}) == Approx(5.0 / 6.0).margin(1e-12));
  CHECK(geometry::inside_mesh(box, {0.5, 0.5, 0.5}));
  // Outside, the five faces are what cancels the missing lid in the closed cube: minus the
  // lid's share, whose sign flips with the side of its plane the point is on (seen from
  // above, the side away from the inside, the lid counts negative, so the rest positive).
  CHECK(geometry::winding_number(box, {0.5, 0.5, 1.5}) ==
        Approx(square_share(1.0, 0.5)).margin(1e-12));
  CHECK_FALSE(geometry::inside_mesh(box, {0.5, 0.5, 1.5}));
  // 0.3 below the floor, on the axis: the lid is 1.3 away and seen from the inside's side.
  // One ray straight up crosses the floor once and leaves through the hole: parity calls this
  // point inside; it is not.
  CHECK(geometry::winding_number(box, {0.5, 0.5, -0.3}) ==
        Approx(-square_share(1.0, 1.3)).margin(1e-12));
  CHECK_FALSE(geometry::inside_mesh(box, {0.5, 0.5, -0.3}));
}

}  // namespace
}  // namespace rigdesign
