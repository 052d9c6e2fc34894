// The neighbour search's internals: its distance kernel (AVX2 and portable versions against a
// plain loop) and the statistical outlier removal's answer on any thread count.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "filters/distances_below.hpp"
#include "rigdesign/filters/statistical_outlier.hpp"
#include "support/clouds.hpp"

using namespace rigdesign;

namespace {

/// The kernel's contract written as plainly as possible: squared distances below the bound,
/// in order.
std::vector<float> plain_distances_below(const std::vector<float>& xs, const std::vector<float>& ys,
                                         const std::vector<float>& zs, float px, float py, float pz,
                                         float bound) {
  std::vector<float> kept;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const float dx = xs[i] - px;
    const float dy = ys[i] - py;
    const float dz = zs[i] - pz;
    const float squared = dx * dx + dy * dy + dz * dz;
    if (squared < bound) kept.push_back(squared);
  }
  return kept;
}

}  // namespace

TEST_CASE(
    "the distance kernel keeps exactly the distances below the bound, in order, on both versions") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
  for (std::uint32_t n = 0; n <= 41; ++n) {  // every tail length of the 8-lane version
    std::vector<float> xs(n), ys(n), zs(n);
    for (std::size_t i = 0; i < n; ++i) {
      xs[i] = coordinate(rng);
      ys[i] = coordinate(rng);
      zs[i] = coordinate(rng);
    }
    const float px = coordinate(rng), py = coordinate(rng), pz = coordinate(rng);
    // One run of all n points, then two runs that skip the point at n / 3 (as a query skips
    // itself).
    const std::uint32_t skipped = n / 3;
    const std::vector<std::vector<filters::IndexRun>> layouts = {
        {{0, n}}, {{0, skipped}, {std::min(n, skipped + 1), n}}};
    for (const std::vector<filters::IndexRun>& runs : layouts) {
      std::vector<float> run_xs, run_ys, run_zs;
      for (const filters::IndexRun& run : runs) {
        run_xs.insert(run_xs.end(), xs.begin() + run.begin, xs.begin() + run.end);
        run_ys.insert(run_ys.end(), ys.begin() + run.begin, ys.begin() + run.end);
        run_zs.insert(run_zs.end(), zs.begin() + run.begin, zs.begin() + run.end);
      }
      for (const float bound : {0.0f, 1.0f, 6.0f, INFINITY}) {
        const std::vector<float> expected =
            plain_distances_below(run_xs, run_ys, run_zs, px, py, pz, bound);
        std::vector<float> out(n + 8, -1.0f);
        const std::size_t kept =
            filters::append_distances_below_portable(xs.data(), ys.data(), zs.data(), runs.data(),
                                                     runs.size(), px, py, pz, bound, out.data());
        CHECK(std::vector<float>(out.begin(), out.begin() + static_cast<long>(kept)) == expected);
        if (filters::distances_below_use_avx2()) {
          std::fill(out.begin(), out.end(), -1.0f);
          const std::size_t kept_avx2 =
              filters::append_distances_below_avx2(xs.data(), ys.data(), zs.data(), runs.data(),
                                                   runs.size(), px, py, pz, bound, out.data());
          CHECK(std::vector<float>(out.begin(), out.begin() + static_cast<long>(kept_avx2)) ==
                expected);
        }
      }
    }
  }
}

TEST_CASE("statistical outlier removal keeps the same points on any thread count") {
  // 16,900 floor points: enough for two threads (8,000 points each at least).
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<model::Point3f> points = test::noisy_floor(2.6, 0.02, 0.002, rng);
  for (int i = 0; i < 60; ++i)
    points.emplace_back(2.6f * unit(rng), 2.6f * unit(rng), 0.3f + 0.3f * unit(rng));
  const model::PointCloud cloud = test::cloud_of(points);
  const std::vector<std::uint32_t> expected = test::brute_force_inliers(points, 10);
  for (const int threads : {1, 2, 3}) {
    model::StatisticalOutlierParams params;
    params.threads = threads;
    CHECK(filters::statistical_outlier_inliers(cloud, params) == expected);
  }
}
