// Floor removal 1 and 2 (paper 1, section 3): the floor is searched in the pass-through slice
// only, so a larger horizontal surface above it (a table top, a bed, a loading dock) is never
// taken for the floor and removed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/filters/pipeline.hpp"
#include "support/clouds.hpp"

using namespace rigdesign;
using test::cloud_of;

namespace {

// A square of points on a `spacing` grid, cell centres: side / spacing points a side, at
// height z(x) over the square [x0, x0 + side] x [y0, y0 + side].
template <typename Height>
void add_square(std::vector<model::Point3f>& points, double x0, double y0, double side,
                double spacing, Height height) {
  const int n = static_cast<int>(std::lround(side / spacing));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = x0 + (i + 0.5) * spacing;
      const double y = y0 + (j + 0.5) * spacing;
      points.emplace_back(static_cast<float>(x), static_cast<float>(y),
                          static_cast<float>(height(x)));
    }
  }
}

std::size_t count_if_z(const model::PointCloud& cloud, float low, float high) {
  return static_cast<std::size_t>(
      std::count_if(cloud.points.begin(), cloud.points.end(),
                    [&](const model::Point3f& p) { return p.z() >= low && p.z() <= high; }));
}

}  // namespace

TEST_CASE("floor removal 1 and 2 keep a table top larger than the visible floor", "[filters]") {
  // Floor 1 x 1 m at 2 cm: 50 x 50 = 2,500 points at z = 0. Table top 2 x 2 m at 2 cm, 0.7 m
  // up: 100 x 100 = 10,000 points, the largest horizontal plane of the cloud by four times.
  std::vector<model::Point3f> points;
  add_square(points, 0.0, 0.0, 1.0, 0.02, [](double) { return 0.0; });
  add_square(points, 1.5, -0.5, 2.0, 0.02, [](double) { return 0.7; });
  REQUIRE(points.size() == 12500);
  model::PointCloud cloud = cloud_of(points);
  cloud.origin = model::Point3f(0, 0, 1.2f);

  // The premise: a plane search over the whole cloud takes the table (ransac_plane, any plane,
  // removes its 10,000 points), as floor removal 2 without a slice did.
  const model::PointCloud no_table = filters::run_stage(model::RemovePlaneParams{}, cloud);
  CHECK(count_if_z(no_table, 0.65f, 0.75f) == 0);
  CHECK(count_if_z(no_table, -0.01f, 0.01f) == 2500);

  for (int variant = 1; variant <= 2; ++variant) {
    INFO("floor removal " << variant);
    const model::PointCloud rest =
        variant == 1 ? filters::remove_floor_1(cloud) : filters::remove_floor_2(cloud);
    CHECK(count_if_z(rest, 0.65f, 0.75f) == 10000);  // the whole table kept
    CHECK(count_if_z(rest, -0.01f, 0.01f) == 0);     // the whole floor removed
    CHECK(rest.size() == 10000);
  }
}

TEST_CASE("floor removal 2 removes only inside the slice, as floor removal 1", "[filters]") {
  // A floor rising 5 degrees along x (within the 15-degree guard), x in [0, 2] m at 2 cm:
  // z = x tan 5 deg leaves the 10 cm slice at x = 0.1 / tan 5 deg = 1.143 m. Columns at
  // x = 0.01 + 0.02 i: i = 57 (x = 1.15, z = 0.1006) to 99 are above it: 43 columns x 100.
  const double slope = std::tan(5.0 * M_PI / 180.0);
  std::vector<model::Point3f> points;
  add_square(points, 0.0, 0.0, 2.0, 0.02, [&](double x) { return x * slope; });
  const model::PointCloud cloud = cloud_of(points);
  for (int variant = 1; variant <= 2; ++variant) {
    INFO("floor removal " << variant);
    const model::PointCloud rest =
        variant == 1 ? filters::remove_floor_1(cloud) : filters::remove_floor_2(cloud);
    CHECK(rest.size() == 43 * 100);
    CHECK(count_if_z(rest, -1.0f, 0.1f) == 0);
  }
}

TEST_CASE("floor removal 2 ignores a plane in the slice tilted beyond its guard", "[filters]") {
  // Only a ramp at 30 degrees (x, y in [0, 0.6] m at 1 cm; the slice holds x <= 0.1 / tan 30
  // deg = 0.173 m), searched on a 3 cm copy so RANSAC has about a hundred centroids: every
  // plane through three of them is the ramp, 30 degrees from horizontal, beyond the 15-degree
  // guard, so no plane is found and nothing is removed. Floor removal 1 has no guard.
  const double slope = std::tan(30.0 * M_PI / 180.0);
  std::vector<model::Point3f> points;
  add_square(points, 0.0, 0.0, 0.6, 0.01, [&](double x) { return x * slope; });
  const model::PointCloud cloud = cloud_of(points);
  model::FloorRemoval2Params params;
  params.coarse_leaf = 0.03;
  CHECK(filters::remove_floor_2(cloud, params).size() == cloud.size());
  CHECK(filters::remove_floor_1(cloud).size() < cloud.size());
}
