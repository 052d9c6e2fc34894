#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <random>

#include "rigdesign/filters/pipeline.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/clouds.hpp"

using namespace rigdesign;

using test::brute_force_inliers;
using test::cloud_of;
using test::noisy_floor;

TEST_CASE("voxel grid returns each voxel's centroid") {
  // Leaf 1 m: (0.1, 0.1, 0.1) and (0.3, 0.5, 0.2) share voxel (0, 0, 0), centroid
  // (0.2, 0.3, 0.15); (1.5, 0.2, 0.2) is alone in voxel (1, 0, 0).
  model::VoxelGridParams params;
  params.leaf = 1.0;
  model::PointCloud result = filters::voxel_grid(
      cloud_of({{0.1f, 0.1f, 0.1f}, {1.5f, 0.2f, 0.2f}, {0.3f, 0.5f, 0.2f}}), params);
  REQUIRE(result.size() == 2);
  std::sort(result.points.begin(), result.points.end(),
            [](const model::Point3f& a, const model::Point3f& b) { return a.x() < b.x(); });
  CHECK(result.points[0].isApprox(model::Point3f(0.2f, 0.3f, 0.15f), 1e-6f));
  CHECK(result.points[1].isApprox(model::Point3f(1.5f, 0.2f, 0.2f), 1e-6f));
  // With boundaries at multiples of 1 m, 0.4 and 0.6 share a voxel; shifted by half a leaf
  // (boundaries at 0.5, 1.5, ...) they fall on opposite sides.
  const model::PointCloud straddling = cloud_of({{0.4f, 0.7f, 0.7f}, {0.6f, 0.7f, 0.7f}});
  CHECK(filters::voxel_grid(straddling, params).size() == 1);
  params.grid_offset = Eigen::Vector3d(0.5, 0.5, 0.5);
  CHECK(filters::voxel_grid(straddling, params).size() == 2);
}

namespace {

/// Voxel centroids by a std::map: PCL's voxel index floor((p - offset) / leaf) taken in float
/// as PCL does, sums in float in input order; sorted, to compare as sets.
std::vector<model::Point3f> map_voxel_centroids(const std::vector<model::Point3f>& points,
                                                float leaf) {
  struct Sums {
    float x = 0, y = 0, z = 0;
    int n = 0;
  };
  std::map<std::array<int, 3>, Sums> voxels;
  const float inverse = 1.0f / leaf;
  for (const model::Point3f& p : points) {
    Sums& s = voxels[{static_cast<int>(std::floor(p.x() * inverse)),
                      static_cast<int>(std::floor(p.y() * inverse)),
                      static_cast<int>(std::floor(p.z() * inverse))}];
    s.x += p.x();
    s.y += p.y();
    s.z += p.z();
    ++s.n;
  }
  std::vector<model::Point3f> centroids;
  for (const auto& [index, s] : voxels) {
    const float n = static_cast<float>(s.n);
    centroids.emplace_back(s.x / n, s.y / n, s.z / n);
  }
  std::sort(centroids.begin(), centroids.end(), [](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return centroids;
}

std::vector<model::Point3f> sorted(std::vector<model::Point3f> points) {
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return points;
}

}  // namespace

TEST_CASE("voxel grid equals a map of voxel sums on clouds of every size, call after call") {
  // The table keeps its memory between calls and sizes itself from the previous call: a large
  // cloud (the table doubles several times), then a small one, then a shuffled one (no scan
  // order for the recent-voxel cache to exploit), then the large one again.
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
  std::vector<model::Point3f> large;
  for (int i = 0; i < 60000; ++i)
    large.emplace_back(coordinate(rng), coordinate(rng), 0.1f * coordinate(rng));
  std::vector<model::Point3f> small(large.begin(), large.begin() + 500);
  std::vector<model::Point3f> scan;  // rows of a scan: consecutive points share voxels
  for (int row = 0; row < 200; ++row) {
    for (int column = 0; column < 300; ++column)
      scan.emplace_back(0.004f * static_cast<float>(column), 0.004f * static_cast<float>(row),
                        1.0f);
  }
  std::vector<model::Point3f> shuffled = scan;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  model::VoxelGridParams params;
  params.leaf = 0.03;
  for (const std::vector<model::Point3f>* points : {&large, &small, &scan, &shuffled, &large}) {
    const model::PointCloud result = filters::voxel_grid(cloud_of(*points), params);
    CHECK(sorted(result.points) == map_voxel_centroids(*points, 0.03f));
  }
}

TEST_CASE("voxel grid refuses a leaf that is not positive or would overflow voxel indices") {
  const model::PointCloud cloud = cloud_of({{0, 0, 0}, {100, 0, 0}});
  model::VoxelGridParams params;
  params.leaf = 0.0;
  CHECK_THROWS_AS(filters::voxel_grid(cloud, params), model::InputError);
  params.leaf = 1e-5;  // 100 m / 10 um = 1e7 voxels along x > 2^21
  try {
    filters::voxel_grid(cloud, params);
    FAIL("expected an error");
  } catch (const model::InputError& error) {
    CHECK(error.diagnostics().front().field == "voxel_grid.leaf");
    CHECK(error.diagnostics().front().problem.find("overflow") != std::string::npos);
  }
  params.leaf = 1e-4;  // 1e6 voxels: fits
  CHECK(filters::voxel_grid(cloud, params).size() == 2);
}

TEST_CASE("statistical outlier removal matches a brute-force neighbour search") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<model::Point3f> points = noisy_floor(1.0, 0.02, 0.002, rng);
  for (int i = 0; i < 40; ++i)
    points.emplace_back(unit(rng), unit(rng), 0.2f + 0.5f * std::abs(unit(rng)));
  const model::PointCloud cloud = cloud_of(points);
  const std::vector<std::uint32_t> expected = brute_force_inliers(points, 10);
  for (const double cell : {0.0, 0.01, 0.05, 0.5}) {  // the cell changes speed, never results
    model::StatisticalOutlierParams params;
    params.cell = cell;
    CHECK(filters::statistical_outlier_inliers(cloud, params) == expected);
  }
  // Every planted outlier goes; the floor stays.
  const std::vector<std::uint32_t> kept = filters::statistical_outlier_inliers(cloud);
  const std::size_t floor_points = points.size() - 40;
  CHECK(std::count_if(kept.begin(), kept.end(),
                      [&](std::uint32_t i) { return i >= floor_points; }) == 0);
  CHECK(static_cast<double>(kept.size()) >= 0.8 * static_cast<double>(floor_points));
}

TEST_CASE("statistical outlier removal: duplicates, far loners and fewer points than neighbours") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<model::Point3f> points;
  for (int i = 0; i < 300; ++i) points.emplace_back(unit(rng), unit(rng), 0.1f * unit(rng));
  for (int i = 0; i < 20; ++i)
    points.push_back(points[static_cast<std::size_t>(i) * 7]);  // exact duplicates
  points.emplace_back(40.0f, -30.0f, 5.0f);  // far from everything: the search radius must grow
  points.emplace_back(40.5f, -30.0f, 5.0f);
  for (const double cell : {0.0, 0.003, 0.2}) {
    model::StatisticalOutlierParams params;
    params.cell = cell;
    CHECK(filters::statistical_outlier_inliers(cloud_of(points), params) ==
          brute_force_inliers(points, 10));
  }
  // Issue 16: cells no grid can hold (a length_error, then undefined casts) and a loner at the
  // readers' coordinate limit change the speed, never the answer.
  for (const double cell : {1e-30, 1e-300, 1e30, 1e300}) {
    model::StatisticalOutlierParams params;
    params.cell = cell;
    CHECK(filters::statistical_outlier_inliers(cloud_of(points), params) ==
          brute_force_inliers(points, 10));
  }
  std::vector<model::Point3f> with_far_loner = points;
  with_far_loner.emplace_back(1e8f, -1e8f, 1e8f);
  const std::vector<std::uint32_t> kept =
      filters::statistical_outlier_inliers(cloud_of(with_far_loner));
  CHECK(kept == brute_force_inliers(with_far_loner, 10));
  CHECK(kept.back() != with_far_loner.size() - 1);  // the loner goes
  const std::vector<model::Point3f> few = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {9, 9, 9}};
  CHECK(filters::statistical_outlier_inliers(cloud_of(few)) ==
        brute_force_inliers(few, 10));  // k > n - 1
}

TEST_CASE("RANSAC recovers a known plane within 1 degree with 30 % outliers") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::normal_distribution<float> noise(0.0f, 0.005f);
  // Plane tilted 10 degrees about x: normal (0, -sin 10, cos 10).
  const Eigen::Vector3f normal(0.0f, -std::sin(0.17453293f), std::cos(0.17453293f));
  const Eigen::Vector3f u = Eigen::Vector3f::UnitX();
  const Eigen::Vector3f v = normal.cross(u);
  std::vector<model::Point3f> points;
  for (int i = 0; i < 700; ++i)
    points.push_back(unit(rng) * u + unit(rng) * v + noise(rng) * normal);
  for (int i = 0; i < 300; ++i) points.emplace_back(unit(rng), unit(rng), unit(rng));
  const model::PointCloud cloud = cloud_of(points);
  const filters::PlaneFit fit =
      filters::fit_plane_ransac(cloud, model::RansacPlaneParams{100, 0.03, 42, 0.99, {}});
  REQUIRE(fit.found);
  const double angle = std::acos(std::min(1.0, std::abs(fit.normal.dot(normal.cast<double>()))));
  CHECK(angle < 1.0 * 3.141592653589793 / 180);
  CHECK(fit.inliers.size() >= 690);
  // Deterministic: the same seed, the same plane.
  CHECK(
      filters::fit_plane_ransac(cloud, model::RansacPlaneParams{100, 0.03, 42, 0.99, {}}).inliers ==
      fit.inliers);
  // Adaptive stop: with ~70 % inliers (some outliers fall within T too), an all-inlier sample
  // is missed with probability (1 - 0.7^3)^k, below 1 % after k = ln 0.01 / ln(1 - 0.343) = 11;
  // a higher share found early stops sooner. Confidence 1 tries every hypothesis.
  CHECK(fit.hypotheses >= 1);
  CHECK(fit.hypotheses <= 11);
  CHECK(filters::fit_plane_ransac(cloud, model::RansacPlaneParams{100, 0.03, 42, 1.0, {}})
            .hypotheses == 100);
}

TEST_CASE("floor removal drops the floor and keeps a 5 cm box standing on it") {
  std::mt19937 rng(3);
  std::vector<model::Point3f> points = noisy_floor(2.0, 0.01, 0.004, rng);
  const std::size_t floor_points = points.size();
  for (double x = 0.3; x < 0.5; x += 0.005) {  // the box's top face, 20 x 20 cm at 5 cm
    for (double y = 0.3; y < 0.5; y += 0.005) points.emplace_back(float(x), float(y), 0.05f);
  }
  const std::size_t box_points = points.size() - floor_points;
  model::PointCloud cloud = cloud_of(points);
  cloud.origin = model::Point3f(0, 0, 0.8f);
  const auto count_box = [](const model::PointCloud& c) {
    return std::count_if(c.points.begin(), c.points.end(),
                         [](const model::Point3f& p) { return p.z() > 0.045f; });
  };
  for (int variant = 1; variant <= 2; ++variant) {
    INFO("floor removal " << variant);
    const model::PointCloud rest =
        variant == 1 ? filters::remove_floor_1(cloud) : filters::remove_floor_2(cloud);
    const auto box_left = static_cast<std::size_t>(count_box(rest));
    const std::size_t floor_left = rest.size() - box_left;
    CHECK(floor_left <= floor_points / 100);
    CHECK(box_left * 100 >= box_points * 99);
  }
}

TEST_CASE("negative obstacles: mirrored point and virtual point on the ray to the floor") {
  model::PointCloud cloud = cloud_of({{2.0f, 0.0f, -0.5f}, {1.0f, 1.0f, -0.01f}});
  cloud.origin = model::Point3f(0, 0, 1.0f);
  const model::PointCloud marked = filters::mark_negative_obstacles(cloud);
  REQUIRE(marked.size() == 3);
  CHECK(marked.points[0].isApprox(model::Point3f(2.0f, 0.0f, 0.5f)));    // mirrored
  CHECK(marked.points[1].isApprox(model::Point3f(1.0f, 1.0f, -0.01f)));  // above -2 cm: kept as is
  // s = o_z / (o_z - z) = 1 / 1.5: P'' = (2 * 2/3, 0, 0.1).
  CHECK(marked.points[2].isApprox(model::Point3f(4.0f / 3.0f, 0.0f, 0.1f), 1e-6f));
}

TEST_CASE("pipelines P1-P4 run their stages in paper 1's orders") {
  CHECK(model::stage_name(filters::preset_pipeline("P3")->stages[1]) == "floor_removal_1");
  CHECK(model::stage_name(filters::preset_pipeline("P4")->stages[2]) == "floor_removal_2");
  CHECK(model::stage_name(filters::preset_pipeline("P1")->stages[0]) == "statistical_outlier");
  CHECK_FALSE(filters::preset_pipeline("P5").has_value());
  std::mt19937 rng(9);
  const model::PointCloud cloud = cloud_of(noisy_floor(2.0, 0.01, 0.004, rng));
  for (const char* name : {"P1", "P2", "P3", "P4"}) {
    std::vector<filters::StageRun> runs;
    const model::PointCloud out =
        filters::run_pipeline(*filters::preset_pipeline(name), cloud, &runs);
    REQUIRE(runs.size() == 3);
    CHECK(runs.front().points_in == cloud.size());
    CHECK(runs.back().points_out == out.size());
    CHECK(out.size() < cloud.size() / 100);  // a bare floor: almost nothing is left
  }
}
