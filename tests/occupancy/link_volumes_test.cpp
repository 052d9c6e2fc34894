// Issue 54 item 2: paper 3's link volumes (eqs. 1-4 as we read them) on hand cases, and the
// person's volumes holding every point of the person's mesh surface.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/occupancy/occupancy_link_volumes.hpp"
#include "rigdesign/sim/scene_library.hpp"

using namespace rigdesign;

namespace {

sim::BodyLink cylinder_along_z() {  // r 0.1 from z = 0 to z = 1
  return {"c", model::Vec3(0, 0, 0), model::Vec3(0, 0, 1), sim::LinkShape::cylinder, 0.1, 0, 0};
}

sim::BodyLink prism_down_z() {  // paper 3's 0.2 (depth, x) x 0.3 (width, y), z 1 down to 0
  return {"p", model::Vec3(0, 0, 1), model::Vec3(0, 0, 0), sim::LinkShape::prism, 0, 0.3, 0.2};
}

}  // namespace

TEST_CASE("a cylinder link holds the points within its radius between its joints", "[occupancy]") {
  const sim::BodyLink link = cylinder_along_z();
  CHECK(occupancy::in_link_volume(link, {0.09, 0, 0.5}));
  CHECK_FALSE(occupancy::in_link_volume(link, {0.11, 0, 0.5}));
  CHECK(occupancy::in_link_volume(link, {0.05, 0.05, 0.5}));        // 0.0707 from the axis
  CHECK_FALSE(occupancy::in_link_volume(link, {0.08, 0.08, 0.5}));  // 0.113
  CHECK_FALSE(occupancy::in_link_volume(link, {0, 0, 1.01}));       // past the end joint
  CHECK_FALSE(occupancy::in_link_volume(link, {0, 0, -0.01}));
  CHECK(occupancy::in_link_volume(link, {0, 0.1, 0.0}));  // the rim of the start cap
  // A link of zero length holds nothing.
  sim::BodyLink point = link;
  point.end = point.start;
  CHECK_FALSE(occupancy::in_link_volume(point, {0, 0, 0}));
}

TEST_CASE("a prism link holds half its width across the body and half its depth front-back",
          "[occupancy]") {
  const sim::BodyLink link = prism_down_z();
  CHECK(occupancy::in_link_volume(link, {0, 0.14, 0.5}));
  CHECK_FALSE(occupancy::in_link_volume(link, {0, 0.16, 0.5}));
  CHECK(occupancy::in_link_volume(link, {0.09, 0, 0.5}));
  CHECK_FALSE(occupancy::in_link_volume(link, {0.11, 0, 0.5}));
  CHECK(occupancy::in_link_volume(link, {-0.09, -0.14, 0.99}));  // a corner
  CHECK_FALSE(occupancy::in_link_volume(link, {0, 0, 1.05}));
}

TEST_CASE("points in links follow the actor's pose", "[occupancy]") {
  // The actor at (2, 1) turned 90 deg: its y axis points along the world's -x.
  const model::Pose3 T_world_actor =
      Eigen::Translation3d(2, 1, 0) * Eigen::AngleAxisd(std::numbers::pi / 2, model::Vec3::UnitZ());
  const std::vector<sim::BodyLink> links{prism_down_z()};
  model::PointCloud cloud;
  cloud.points = {{2.0f - 0.14f, 1.0f, 0.5f},  // actor y = 0.14: inside the width
                  {2.0f, 1.0f + 0.14f, 0.5f},  // actor x = 0.14: outside the depth (0.1)
                  {2.0f, 1.0f + 0.09f, 0.5f},  // actor x = 0.09: inside
                  {5.0f, 5.0f, 0.5f}};
  const std::vector<model::PointCloud> clouds{cloud};
  const std::vector<model::Vec3> inside = occupancy::points_in_links(clouds, T_world_actor, links);
  REQUIRE(inside.size() == 2);
  CHECK(inside[0].x() == Approx(1.86));
  CHECK(inside[1].y() == Approx(1.09));
}

TEST_CASE("the person's link volumes hold every point of the person's surface", "[occupancy]") {
  // Independent of the links' layout: sample each triangle of the cell's walking person on a
  // barycentric grid (10 steps a side) and test every sample in the person's own frame.
  const model::Scene cell = sim::make_scene("cell", 1);
  REQUIRE_FALSE(cell.moving.empty());
  const model::TriangleMesh& body = cell.moving.front().mesh;
  const std::vector<sim::BodyLink> links = sim::person_links();
  std::size_t samples = 0, outside = 0;
  for (const auto& triangle : body.triangles) {
    const model::Vec3& a = body.vertices[static_cast<std::size_t>(triangle[0])];
    const model::Vec3& b = body.vertices[static_cast<std::size_t>(triangle[1])];
    const model::Vec3& c = body.vertices[static_cast<std::size_t>(triangle[2])];
    for (int i = 0; i <= 10; ++i) {
      for (int j = 0; i + j <= 10; ++j) {
        const model::Vec3 p = a + (b - a) * (i / 10.0) + (c - a) * (j / 10.0);
        ++samples;
        const bool held = std::any_of(links.begin(), links.end(), [&](const sim::BodyLink& link) {
          return occupancy::in_link_volume(link, p);
        });
        outside += !held;
      }
    }
  }
  CHECK(samples > 1000);
  CHECK(outside == 0);
  // And a point 0.1 m in front of the chest (the torso's front face is at x = 0.12) is not
  // the person's.
  CHECK_FALSE(std::any_of(links.begin(), links.end(), [](const sim::BodyLink& link) {
    return occupancy::in_link_volume(link, {0.25, 0.0, 1.2});
  }));
}
