#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <utility>

#include "rigdesign/geometry/body_mesh.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/fov_mesh.hpp"
#include "rigdesign/render/view_3d_figure.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

model::SensorMode pyramid_mode(double horizontal_deg, double vertical_deg, double min_range,
                               double max_range) {
  model::SensorMode mode;
  mode.fov = model::FieldOfView(
      model::pyramid_fov(model::deg_to_rad(horizontal_deg), model::deg_to_rad(vertical_deg)));
  mode.min_range = min_range;
  mode.max_range = max_range;
  return mode;
}

model::SensorMode cone_mode(double apex_deg, double min_range, double max_range) {
  model::SensorMode mode;
  mode.fov = model::FieldOfView(model::cone_fov(model::deg_to_rad(apex_deg)));
  mode.min_range = min_range;
  mode.max_range = max_range;
  return mode;
}

// A spinning lidar's band, or with `planar` a 2D scanner's wedge (symmetric about the x-y plane).
enum class Scan { band, planar };

model::SensorMode band_mode(Scan kind, double span_deg, double elevation_min_deg,
                            double elevation_max_deg, double min_range, double max_range) {
  model::SensorMode mode;
  const double span = model::deg_to_rad(span_deg);
  mode.fov = model::FieldOfView(
      kind == Scan::band
          ? model::band_fov(span, model::deg_to_rad(elevation_min_deg),
                            model::deg_to_rad(elevation_max_deg))
          : model::planar_fov(span, model::deg_to_rad(elevation_max_deg - elevation_min_deg)));
  mode.min_range = min_range;
  mode.max_range = max_range;
  return mode;
}

// A mount somewhere on the robot, tilted, so the tests also exercise the pose.
model::Pose3 tilted_mount() {
  return model::pose_from_xyz_rpy(model::Vec3(0.3, -0.1, 0.45), model::Vec3(0.1, 0.35, -0.6));
}

// Volume enclosed by a closed, outward-wound mesh: the divergence theorem as a sum of signed
// tetrahedra with the origin.
double enclosed_volume(const model::TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const auto& [a, b, c] : mesh.triangles) {
    six_volume += mesh.vertices[a].dot(mesh.vertices[b].cross(mesh.vertices[c]));
  }
  return six_volume / 6;
}

// Closed and consistently wound: every directed edge is used once and its reverse once.
bool is_closed_and_oriented(const model::TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& [a, b, c] : mesh.triangles) {
    ++uses[{a, b}];
    ++uses[{b, c}];
    ++uses[{c, a}];
  }
  for (const auto& [edge, count] : uses) {
    const auto reverse = uses.find({edge.second, edge.first});
    if (count != 1 || reverse == uses.end() || reverse->second != 1) return false;
  }
  return !mesh.triangles.empty();
}

// (r1^3 - r0^3) / 3 times the solid angle: the volume of a spherical-shell sector.
double shell_sector_volume(double solid_angle, double r0, double r1) {
  return solid_angle * (r1 * r1 * r1 - r0 * r0 * r0) / 3;
}

model::RobotBody cylinder_body(double radius, double height) {
  model::RobotBody body;
  body.radius = radius;
  body.height = height;
  return body;
}

model::RobotBody square_body(const model::Vec2& centre, double half_side, double height) {
  model::RobotBody body;
  body.height = height;
  body.radius = half_side * std::numbers::sqrt2 + centre.norm();
  for (const model::Vec2& corner :
       {model::Vec2(-1, -1), model::Vec2(1, -1), model::Vec2(1, 1), model::Vec2(-1, 1)}) {
    body.footprint.push_back(centre + half_side * corner);
  }
  return body;
}

const std::uint8_t* pixel(const std::vector<std::uint8_t>& rgba, int width, int column, int row) {
  return &rgba[(static_cast<std::size_t>(row) * width + column) * 4];
}

std::uint32_t big_endian_u32(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    value = (value << 8) | static_cast<unsigned char>(bytes[offset + i]);
  }
  return value;
}

}  // namespace

TEST_CASE("a pyramid FOV mesh stays inside its angles and range, far cap at the truncation") {
  const model::SensorMode mode = pyramid_mode(75, 65, 0.5, 5.46);
  const model::Pose3 T_robot_sensor = tilted_mount();
  const model::TriangleMesh mesh = render::fov_mesh(mode, T_robot_sensor, 3.0);
  REQUIRE_FALSE(mesh.vertices.empty());
  int on_far_cap = 0;
  for (const model::Vec3& vertex : mesh.vertices) {
    const model::Vec3 q = T_robot_sensor.inverse() * vertex;
    const double distance = q.norm();
    // Only cap vertices: the walls are planar and need none of their own.
    CHECK((std::abs(distance - 0.5) < 1e-9 || std::abs(distance - 3.0) < 1e-9));
    if (std::abs(distance - 3.0) < 1e-9) ++on_far_cap;
    CHECK(q.x() > 0);
    CHECK(std::abs(std::atan(q.y() / q.x())) <= mode.fov.horizontal() / 2 + 1e-9);
    CHECK(std::abs(std::atan(q.z() / q.x())) <= mode.fov.vertical() / 2 + 1e-9);
  }
  CHECK(on_far_cap * 2 == static_cast<int>(mesh.vertices.size()));
  CHECK(is_closed_and_oriented(mesh));
}

TEST_CASE("a 360-degree band mesh reaches both elevation limits all round") {
  const model::SensorMode vlp16 = band_mode(Scan::band, 360, -15, 15, 0.9, 100);
  const model::TriangleMesh mesh = render::fov_mesh(vlp16, model::Pose3::Identity(), 4.0);
  double lowest = std::numbers::pi;
  double highest = -std::numbers::pi;
  int behind = 0;
  for (const model::Vec3& q : mesh.vertices) {
    const double elevation = std::asin(q.z() / q.norm());
    lowest = std::min(lowest, elevation);
    highest = std::max(highest, elevation);
    if (q.x() < -0.5) ++behind;
  }
  CHECK_THAT(lowest, WithinAbs(model::deg_to_rad(-15), 1e-9));
  CHECK_THAT(highest, WithinAbs(model::deg_to_rad(15), 1e-9));
  CHECK(behind > 0);
  CHECK(is_closed_and_oriented(mesh));
}

TEST_CASE("FOV mesh volumes match the spherical-shell sectors they tessellate") {
  const model::Pose3 T_robot_sensor = tilted_mount();
  SECTION("cone from the sensor origin") {
    const double half_apex = model::deg_to_rad(30);
    const model::TriangleMesh mesh =
        render::fov_mesh(cone_mode(60, 0.0, 2.0), T_robot_sensor, 10.0);
    const double exact =
        shell_sector_volume(2 * std::numbers::pi * (1 - std::cos(half_apex)), 0.0, 2.0);
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinRel(exact, 0.02));
  }
  SECTION("cone with a minimum range") {
    const double half_apex = model::deg_to_rad(45);
    const model::TriangleMesh mesh =
        render::fov_mesh(cone_mode(90, 0.3, 2.5), T_robot_sensor, 10.0);
    const double exact =
        shell_sector_volume(2 * std::numbers::pi * (1 - std::cos(half_apex)), 0.3, 2.5);
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinRel(exact, 0.02));
  }
  SECTION("full-circle band") {
    const model::TriangleMesh mesh =
        render::fov_mesh(band_mode(Scan::band, 360, -15, 15, 0.9, 100), T_robot_sensor, 4.0);
    const double exact = shell_sector_volume(
        2 * std::numbers::pi * (std::sin(model::deg_to_rad(15)) - std::sin(model::deg_to_rad(-15))),
        0.9, 4.0);
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinRel(exact, 0.02));
  }
  SECTION("band up to the zenith, from the sensor origin") {
    const model::TriangleMesh mesh =
        render::fov_mesh(band_mode(Scan::band, 360, -30, 90, 0.0, 3.0), T_robot_sensor, 10.0);
    const double exact =
        shell_sector_volume(2 * std::numbers::pi * (1 - std::sin(model::deg_to_rad(-30))), 0, 3.0);
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinRel(exact, 0.02));
  }
  SECTION("planar 270-degree wedge") {
    const model::TriangleMesh mesh =
        render::fov_mesh(band_mode(Scan::planar, 270, -0.5, 0.5, 0.05, 10), T_robot_sensor, 5.0);
    const double solid_angle = model::deg_to_rad(270) * (std::sin(model::deg_to_rad(0.5)) -
                                                         std::sin(model::deg_to_rad(-0.5)));
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinRel(shell_sector_volume(solid_angle, 0.05, 5.0), 0.02));
  }
  SECTION("pyramid") {
    const model::TriangleMesh mesh =
        render::fov_mesh(pyramid_mode(120, 120, 0.25, 2.88), T_robot_sensor, 10.0);
    // Solid angle of a rectangular pyramid with full angles a, b: 4 asin(sin(a/2) sin(b/2)).
    const double half = model::deg_to_rad(60);
    const double solid_angle = 4 * std::asin(std::sin(half) * std::sin(half));
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh),
               WithinRel(shell_sector_volume(solid_angle, 0.25, 2.88), 0.02));
  }
}

TEST_CASE("an empty range interval gives an empty FOV mesh") {
  CHECK(render::fov_mesh(cone_mode(60, 0.5, 4.0), model::Pose3::Identity(), 0.4).triangles.empty());
}

TEST_CASE("body meshes are closed prisms with the body's volume") {
  SECTION("cylinder") {
    const model::TriangleMesh mesh = geometry::body_mesh(cylinder_body(0.45, 1.2));
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinRel(std::numbers::pi * 0.45 * 0.45 * 1.2, 0.01));
  }
  SECTION("rectangle footprint, exactly") {
    model::RobotBody body;
    body.height = 0.9;
    body.footprint = {model::Vec2(-0.4, -0.3), model::Vec2(0.5, -0.3), model::Vec2(0.5, 0.3),
                      model::Vec2(-0.4, 0.3)};
    const model::TriangleMesh mesh = geometry::body_mesh(body);
    CHECK(is_closed_and_oriented(mesh));
    CHECK_THAT(enclosed_volume(mesh), WithinAbs(0.9 * 0.6 * 0.9, 1e-12));
  }
  SECTION("non-convex footprint, either winding") {
    model::RobotBody body;
    body.height = 0.5;
    // An L of three unit squares; its notch defeats a fan from the first corner.
    body.footprint = {model::Vec2(0, 0), model::Vec2(2, 0), model::Vec2(2, 1),
                      model::Vec2(1, 1), model::Vec2(1, 2), model::Vec2(0, 2)};
    for (const bool reversed : {false, true}) {
      if (reversed) std::reverse(body.footprint.begin(), body.footprint.end());
      const model::TriangleMesh mesh = geometry::body_mesh(body);
      CHECK(is_closed_and_oriented(mesh));
      CHECK_THAT(enclosed_volume(mesh), WithinAbs(3 * 0.5, 1e-12));
    }
  }
}

TEST_CASE("render_view_3d writes a PNG of the requested size") {
  const test::TempFolder folder;
  const std::string path = folder.path() + "/body.png";
  render::View3dSettings settings;
  settings.width = 200;
  settings.height = 150;
  settings.viewpoint = render::Viewpoint::top;
  settings.extent = 1.0;
  render::render_view_3d({{geometry::body_mesh(cylinder_body(0.5, 1.0)), render::kBodyColour, 1.0}},
                         settings, path);

  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 24);
  CHECK(bytes.substr(1, 3) == "PNG");
  // The IHDR chunk follows the 8-byte signature: width, then height, big-endian.
  CHECK(big_endian_u32(bytes, 16) == 200);
  CHECK(big_endian_u32(bytes, 20) == 150);
}

TEST_CASE("a top view shows the body grey on a white background") {
  render::View3dSettings settings;
  settings.width = 200;
  settings.height = 150;
  settings.viewpoint = render::Viewpoint::top;
  settings.extent = 1.0;
  const std::vector<std::uint8_t> rgba = render::render_view_3d_pixels(
      {{geometry::body_mesh(cylinder_body(0.5, 1.0)), render::kBodyColour, 1.0}}, settings);
  REQUIRE(rgba.size() == 200u * 150u * 4u);

  // Inside the body's disc, off the axis arrows drawn from its centre (up for x, left for y).
  const std::uint8_t* body = pixel(rgba, 200, 100 + 18, 75 + 18);
  CHECK(body[0] > 60);
  CHECK(body[0] < 200);
  CHECK(std::abs(body[0] - body[1]) < 15);
  CHECK(body[3] == 255);
  const std::uint8_t* corner = pixel(rgba, 200, 0, 0);
  CHECK(corner[0] > 240);
  CHECK(corner[1] > 240);
  CHECK(corner[2] > 240);
}

TEST_CASE("a top view puts the robot's front up and its left on the left") {
  render::View3dSettings settings;
  settings.width = 120;
  settings.height = 120;
  settings.viewpoint = render::Viewpoint::top;
  settings.extent = 1.0;
  const render::Rgb orange{0.90, 0.62, 0.00};
  const render::Rgb blue{0.00, 0.45, 0.70};
  const std::vector<std::uint8_t> rgba = render::render_view_3d_pixels(
      {{geometry::body_mesh(square_body(model::Vec2(0.7, 0.0), 0.12, 0.3)), orange, 1.0},
       {geometry::body_mesh(square_body(model::Vec2(0.0, 0.7), 0.12, 0.3)), blue, 1.0}},
      settings);
  // 1 m is about 55 px here (the frame spans the 2 m grid plus a small margin); 0.7 m ~ 39 px.
  const std::uint8_t* ahead = pixel(rgba, 120, 60, 60 - 39);
  const std::uint8_t* left = pixel(rgba, 120, 60 - 39, 60);
  const std::uint8_t* behind = pixel(rgba, 120, 60, 60 + 39);
  const std::uint8_t* right = pixel(rgba, 120, 60 + 39, 60);
  CHECK(ahead[0] > ahead[2] + 80);
  CHECK(left[2] > left[0] + 60);
  CHECK(behind[0] > 200);
  CHECK(behind[2] > 200);
  CHECK(right[0] > 200);
  CHECK(right[2] > 200);
}

TEST_CASE("an isometric view blends a translucent FOV over the scene") {
  render::View3dSettings settings;
  settings.width = 120;
  settings.height = 90;
  const render::Rgb blue{0.00, 0.45, 0.70};
  const model::Pose3 T_robot_sensor =
      model::pose_from_xyz_rpy(model::Vec3(0.3, 0, 0.8), model::Vec3::Zero());
  const std::vector<std::uint8_t> rgba = render::render_view_3d_pixels(
      {{geometry::body_mesh(cylinder_body(0.3, 0.8)), render::kBodyColour, 1.0},
       {render::fov_mesh(cone_mode(60, 0.0, 5.0), T_robot_sensor, 1.5), blue, 0.35}},
      settings);
  int tinted = 0;
  int white = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    if (rgba[i + 2] > rgba[i] + 40 && rgba[i] > 80) ++tinted;  // blue over white: light blue
    if (rgba[i] > 250 && rgba[i + 1] > 250 && rgba[i + 2] > 250) ++white;
  }
  CHECK(tinted > 100);
  CHECK(white > 1000);
}

TEST_CASE("render_view_3d_pixels rejects an empty image") {
  render::View3dSettings settings;
  settings.width = 0;
  CHECK_THROWS_AS(render::render_view_3d_pixels({}, settings), std::invalid_argument);
}

TEST_CASE("the visible FOV volume stops at the top plate, as the coverage numbers do") {
  // The UR Cleaner's VLP-16: 1.04 m up on a 0.45 m x 1.0 m cylinder. Beams steeper than
  // atan(0.04 / 0.45) = 5.08 deg down land on the plate; the rest reach d = 3.5 m.
  const model::RobotBody body = cylinder_body(0.45, 1.0);
  const geometry::BodyOccluder occluder(body);
  const model::SensorMode mode = band_mode(Scan::band, 360, -15, 15, 0.9, 100);
  const model::Pose3 mount = model::pose_from_xyz_rpy(model::Vec3(0, 0, 1.04), model::Vec3::Zero());
  const model::TriangleMesh mesh = render::visible_fov_mesh(mode, mount, 3.5, occluder);
  REQUIRE(!mesh.vertices.empty());
  const double cut = std::atan(0.04 / 0.45);
  int shadowed = 0, clear = 0;
  for (const model::Vec3& vertex : mesh.vertices) {
    const model::Vec3 ray = vertex - mount.translation();
    const double reach = ray.norm();
    const double elevation = std::asin(ray.z() / reach);
    if (elevation < -cut - model::deg_to_rad(1.5)) {
      ++shadowed;  // on the plate: at its height, inside its rim
      CHECK(vertex.z() >= 1.0 - 1e-6);
      CHECK(std::hypot(vertex.x(), vertex.y()) <= 0.45 + 1e-6);
    } else if (elevation > -cut + model::deg_to_rad(1.5)) {
      ++clear;  // the near or the far cap, untouched
      CHECK((std::abs(reach - 0.9) < 1e-6 || std::abs(reach - 3.5) < 1e-6));
    }
  }
  CHECK(shadowed > 100);
  CHECK(clear > 100);
}
