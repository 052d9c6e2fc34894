#include "rigdesign/model/scene.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "rigdesign/sim/scene_library.hpp"

using namespace rigdesign;

namespace {

// Open, single-sided surfaces; every other object is built from closed solids.
bool is_floor_plane(const std::string& name) {
  return name == "floor" || name == "lower_floor";
}

const model::SceneObject& scene_object_named(const model::Scene& scene, const std::string& name) {
  for (const model::SceneObject& object : scene.objects) {
    if (object.name == name) return object;
  }
  FAIL("no object named " << name << " in " << scene.name);
  throw std::logic_error("unreachable");
}

bool scene_contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Volume enclosed by a closed mesh (divergence theorem): positive iff normals point out.
double scene_signed_volume(const model::TriangleMesh& mesh) {
  double six_volume = 0;
  for (const auto& t : mesh.triangles) {
    const model::Vec3& a = mesh.vertices[static_cast<std::size_t>(t[0])];
    const model::Vec3& b = mesh.vertices[static_cast<std::size_t>(t[1])];
    const model::Vec3& c = mesh.vertices[static_cast<std::size_t>(t[2])];
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6;
}

// Closed and consistently wound: every directed edge occurs once, its reverse once.
bool watertight(const model::TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i)
      ++edges[{t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]}];
  }
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
  }
  return true;
}

model::Vec3 vertex_centroid(const model::TriangleMesh& mesh) {
  model::Vec3 sum = model::Vec3::Zero();
  for (const model::Vec3& v : mesh.vertices) sum += v;
  return sum / static_cast<double>(mesh.vertices.size());
}

Eigen::AlignedBox3d bounds(const model::TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const model::Vec3& v : mesh.vertices) box.extend(v);
  return box;
}

// Width of the mesh's xy footprint across its long horizontal axis [m].
double horizontal_thickness(const model::TriangleMesh& mesh) {
  Eigen::Vector2d mean = vertex_centroid(mesh).head<2>();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const model::Vec3& v : mesh.vertices) {
    const Eigen::Vector2d d = v.head<2>() - mean;
    covariance += d * d.transpose();
  }
  const Eigen::Vector2d minor =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(covariance).eigenvectors().col(0);
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const model::Vec3& v : mesh.vertices) {
    const double along = minor.dot(v.head<2>());
    low = std::min(low, along);
    high = std::max(high, along);
  }
  return high - low;
}

// Whether `point` lies inside (or on) triangle abc, all in the xy plane.
bool in_triangle_xy(const Eigen::Vector2d& point, const model::Vec3& a, const model::Vec3& b,
                    const model::Vec3& c) {
  auto side = [&](const model::Vec3& p, const model::Vec3& q) {
    return (q.x() - p.x()) * (point.y() - p.y()) - (q.y() - p.y()) * (point.x() - p.x());
  };
  const double s1 = side(a, b);
  const double s2 = side(b, c);
  const double s3 = side(c, a);
  const bool has_negative = s1 < 0 || s2 < 0 || s3 < 0;
  const bool has_positive = s1 > 0 || s2 > 0 || s3 > 0;
  return !(has_negative && has_positive);
}

// Whether a vertical ray through (x, y) meets a triangle lying in the plane z = 0.
bool floor_covers(const model::Scene& scene, const Eigen::Vector2d& point) {
  const model::TriangleMesh all = scene.at(0);
  for (const auto& t : all.triangles) {
    const model::Vec3& a = all.vertices[static_cast<std::size_t>(t[0])];
    const model::Vec3& b = all.vertices[static_cast<std::size_t>(t[1])];
    const model::Vec3& c = all.vertices[static_cast<std::size_t>(t[2])];
    if (a.z() != 0 || b.z() != 0 || c.z() != 0) continue;
    if (in_triangle_xy(point, a, b, c)) return true;
  }
  return false;
}

model::Vec3 person_centroid(const model::Scene& cell, double t) {
  const model::MovingObject& person = cell.moving.at(0);
  model::TriangleMesh posed;
  posed.append(person.mesh, person.T_world_object(t));
  return vertex_centroid(posed);
}

}  // namespace

TEST_CASE("every named scene builds with triangles") {
  REQUIRE(sim::scene_names() ==
          std::vector<std::string>{"office", "corridor", "stairs", "wall_following", "cell"});
  for (const std::string& name : sim::scene_names()) {
    const model::Scene scene = sim::make_scene(name, 1);
    CHECK(scene.name == name);
    CHECK_FALSE(scene.at(0).triangles.empty());
    CHECK(scene_object_named(scene, "floor").mesh.triangles.size() >= 2);
  }
  CHECK_THROWS_AS(sim::make_scene("kitchen", 1), std::invalid_argument);
}

TEST_CASE("scenes are deterministic for a seed, the office's furniture follows the seed") {
  for (const std::string& name : sim::scene_names()) {
    CHECK(sim::make_scene(name, 7).at(3.0).vertices == sim::make_scene(name, 7).at(3.0).vertices);
  }
  const model::Scene seven = sim::make_scene("office", 7);
  const model::Scene eight = sim::make_scene("office", 8);
  CHECK(vertex_centroid(scene_object_named(seven, "table_1_top").mesh) !=
        vertex_centroid(scene_object_named(eight, "table_1_top").mesh));
}

TEST_CASE("closed solids have outward normals and their true volume") {
  for (const std::string& name : sim::scene_names()) {
    const model::Scene scene = sim::make_scene(name, 3);
    for (const model::SceneObject& object : scene.objects) {
      if (is_floor_plane(object.name)) continue;
      INFO(name << ": " << object.name);
      CHECK(watertight(object.mesh));
      CHECK(scene_signed_volume(object.mesh) > 0);
    }
    for (const model::MovingObject& object : scene.moving) {
      INFO(name << ": " << object.name);
      CHECK(watertight(object.mesh));
      CHECK(scene_signed_volume(object.mesh) > 0);
    }
  }
  // Boxes of known size: the cell's 0.8 x 0.6 x 1 m plate, the 1.2 x 0.45 x 0.06 m foam.
  CHECK(scene_signed_volume(scene_object_named(sim::make_scene("cell", 0), "plate").mesh) ==
        Approx(0.8 * 0.6 * 1.0));
  CHECK(
      scene_signed_volume(scene_object_named(sim::make_scene("wall_following", 0), "foam").mesh) ==
      Approx(1.2 * 0.45 * 0.06));
}

TEST_CASE("office chairs stand on thin legs and a cable hangs to the floor") {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const model::Scene office = sim::make_scene("office", seed);
    INFO("seed " << seed);
    int chair_legs = 0;
    for (const model::SceneObject& object : office.objects) {
      if (!scene_contains(object.name, "chair") || !scene_contains(object.name, "_leg_")) continue;
      ++chair_legs;
      CHECK(horizontal_thickness(object.mesh) <= 0.03);
      CHECK(bounds(object.mesh).sizes().z() <= 0.03);
    }
    CHECK(chair_legs >= 3 * 5);  // at least 3 chairs with a five-star base each
    const Eigen::AlignedBox3d cable = bounds(scene_object_named(office, "cable").mesh);
    // Its end rests on the floor: the cord's 5 mm radius above it at most, never below.
    CHECK(cable.min().z() >= 0);
    CHECK(cable.min().z() < 0.005);
    CHECK(cable.max().z() > 0.7);

    // Everything but the floor is at least 1 m (horizontally) from the robot's start, and
    // the robot faces +x, towards the furniture.
    const model::Vec3 robot = office.T_world_robot.translation();
    CHECK(office.T_world_robot.linear().col(0).isApprox(model::Vec3::UnitX()));
    for (const model::SceneObject& object : office.objects) {
      if (object.name == "floor") continue;
      const Eigen::AlignedBox3d box = bounds(object.mesh);
      const Eigen::AlignedBox2d footprint(box.min().head<2>(), box.max().head<2>());
      INFO(object.name);
      CHECK(footprint.exteriorDistance(Eigen::Vector2d(robot.head<2>())) >= 1.0);
      // Furniture stays inside the 8 x 6 m room.
      if (!scene_contains(object.name, "wall")) {
        CHECK(footprint.min().x() >= 0);
        CHECK(footprint.max().x() <= 8);
        CHECK(std::abs(footprint.min().y()) <= 3);
        CHECK(std::abs(footprint.max().y()) <= 3);
      }
    }
  }
}

TEST_CASE("stairs: nothing covers the openings at floor level, and the steps go down") {
  const model::Scene stairs = sim::make_scene("stairs", 0);
  // The stairwell opening is x in [2, 4.5], y in [-0.6, 0.6]; the pit x, y in [1, 1.4].
  const Eigen::Vector2d stairwell_centre(3.25, 0.0);
  const Eigen::Vector2d pit_centre(1.2, 1.2);
  CHECK_FALSE(floor_covers(stairs, stairwell_centre));
  CHECK_FALSE(floor_covers(stairs, pit_centre));
  CHECK(floor_covers(stairs, Eigen::Vector2d(1.0, 0.0)));  // sanity: the floor is there
  CHECK(bounds(stairs.at(0)).min().z() < -0.5);
  CHECK(bounds(scene_object_named(stairs, "lower_floor").mesh).min().z() == Approx(-1.0));
  CHECK(bounds(scene_object_named(stairs, "pit_bottom").mesh).max().z() == Approx(-0.5));
}

TEST_CASE("wall following: the foam top overhangs its legs into the path, low down") {
  const model::Scene scene = sim::make_scene("wall_following", 0);
  const Eigen::AlignedBox3d foam = bounds(scene_object_named(scene, "foam").mesh);
  double legs_path_side = std::numeric_limits<double>::infinity();
  int legs = 0;
  for (const model::SceneObject& object : scene.objects) {
    if (!scene_contains(object.name, "table_leg")) continue;
    ++legs;
    legs_path_side = std::min(legs_path_side, bounds(object.mesh).min().y());
  }
  REQUIRE(legs == 4);
  // The path runs along y = 0 with the wall on the left (+y): the path side is -y.
  CHECK(foam.min().y() < legs_path_side - 0.1);
  CHECK(foam.min().z() > 0.3);
  CHECK(foam.min().z() < 0.5);
  CHECK(scene.T_world_robot.translation().x() < foam.min().x() - 2.5);
}

TEST_CASE("cell: the person walks the ellipse twice in 96 s, facing ahead") {
  const model::Scene cell = sim::make_scene("cell", 0);
  REQUIRE(cell.moving.size() == 1);
  REQUIRE(cell.moving[0].name == "person");
  for (double t : {0.0, 5.0, 12.0, 24.0, 30.0, 48.0, 70.0, 96.0}) {
    const model::Vec3 centroid = person_centroid(cell, t);
    INFO("t = " << t);
    // Within 5 cm of the ellipse F = x^2/4 + y^2/1 - 1 = 0, by the first-order distance
    // |F| / |grad F|.
    const double x = centroid.x();
    const double y = centroid.y();
    const double level = x * x / 4 + y * y - 1;
    CHECK(std::abs(level) / std::hypot(x / 2, 2 * y) < 0.05);
  }
  const model::Vec3 start = person_centroid(cell, 0);
  const model::Vec3 half = person_centroid(cell, 24);
  CHECK(start.head<2>().isApprox(Eigen::Vector2d(2, 0), 1e-9));
  CHECK(half.x() == Approx(-2.0).margin(0.05));
  CHECK(half.y() == Approx(0.0).margin(0.05));
  CHECK((person_centroid(cell, 48) - start).norm() < 0.01);
  CHECK((person_centroid(cell, 96) - start).norm() < 0.01);
  // At (2, 0) going counter-clockwise the tangent is +y.
  const model::Vec3 facing = cell.moving[0].T_world_object(0).linear().col(0);
  CHECK(facing.isApprox(model::Vec3::UnitY(), 1e-9));
  const Eigen::AlignedBox3d body = bounds(cell.moving[0].mesh);
  CHECK(body.sizes().z() == Approx(1.75));
  CHECK(body.sizes().y() == Approx(0.5));
  CHECK(body.min().z() == Approx(0.0));
}
