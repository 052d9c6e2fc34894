// Issue 36 item 1: paper 3's false-positive region, the convex hull of the actor's points.
#include <catch2/catch.hpp>
#include <vector>

#include "rigdesign/occupancy/occupancy_hull_region.hpp"

using namespace rigdesign;

TEST_CASE("hull region: a unit cube's corners and a point inside, by hand", "[occupancy]") {
  std::vector<model::Vec3> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  points.emplace_back(0.5, 0.5, 0.5);  // inside: not a hull vertex
  const occupancy::HullRegion hull(points);
  REQUIRE_FALSE(hull.empty());
  CHECK_FALSE(hull.is_box());
  CHECK(hull.contains({0.5, 0.5, 0.5}, 0.0));
  CHECK(hull.contains({0.99, 0.01, 0.5}, 0.0));
  CHECK_FALSE(hull.contains({1.05, 0.5, 0.5}, 0.0));
  CHECK(hull.contains({1.05, 0.5, 0.5}, 0.05 + 1e-12));  // grown by 5 cm
  CHECK_FALSE(hull.contains({0.5, 0.5, -0.2}, 0.1));
}

TEST_CASE("hull region: a tetrahedron cuts the cube's corner off", "[occupancy]") {
  // Vertices (0,0,0), (1,0,0), (0,1,0), (0,0,1): inside where x + y + z <= 1.
  const std::vector<model::Vec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const occupancy::HullRegion hull(points);
  CHECK(hull.contains({0.3, 0.3, 0.3}, 0.0));        // sum 0.9
  CHECK_FALSE(hull.contains({0.4, 0.4, 0.4}, 0.0));  // sum 1.2: 0.2 / sqrt(3) = 0.115 m out
  CHECK(hull.contains({0.4, 0.4, 0.4}, 0.116));
  CHECK_FALSE(hull.contains({0.4, 0.4, 0.4}, 0.115));
}

TEST_CASE("hull region: points in one plane fall back to their bounding box", "[occupancy]") {
  const std::vector<model::Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}};
  const occupancy::HullRegion hull(flat);
  CHECK(hull.is_box());
  CHECK(hull.contains({0.5, 0.5, 0.0}, 0.0));
  CHECK_FALSE(hull.contains({0.5, 0.5, 0.05}, 0.0));
  CHECK(hull.contains({0.5, 0.5, 0.05}, 0.05));
  CHECK(occupancy::HullRegion(std::vector<model::Vec3>{}).empty());
  CHECK_FALSE(occupancy::HullRegion(std::vector<model::Vec3>{}).contains({0, 0, 0}, 1.0));
}
