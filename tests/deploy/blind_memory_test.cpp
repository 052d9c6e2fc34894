// Issue 14 item 3: the Hit Layer sized from the rig's blind gaps, against a hand computation
// on a coverage built by hand.
#include "rigdesign/deploy/blind_memory.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

using namespace rigdesign;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// One angle per degree; the floor is unseen on [blind_from, blind_to] degrees.
metrics::RigCoverage coverage_with_gap(int blind_from, int blind_to, double r, double d) {
  metrics::RigCoverage coverage;
  coverage.distance = d;
  for (int degree = 0; degree < 360; ++degree) {
    metrics::AngleCoverage angle;
    angle.theta = degree * kDeg;
    angle.r = r;
    angle.floor = degree >= blind_from && degree <= blind_to ? 0.0 : 1.0;
    angle.complete = angle.floor;
    coverage.angles.push_back(angle);
  }
  return coverage;
}

}  // namespace

TEST_CASE("blind memory: a side gap is kept while the robot drives past it", "[deploy]") {
  // Gap 100..140 deg on the left, r = 0.5 m, d = 3 m. A grazing obstacle (y = 0.5) enters at
  // x = 0.5 cot 100 deg = -0.08816 m and leaves at 0.5 cot 140 deg = -0.59588 m: 0.50771 m
  // kept. It is seen from x = sqrt(3^2 - 0.5^2) = 2.95804 m (every azimuth before the gap is
  // covered): 3.04620 m seen. At 5 Hz, 0.25 m/s slowest, 1 m/s fastest:
  // hit_max = ceil(2 x 5 x 0.50771 / 0.25) = ceil(20.31) = 21;
  // hit = ceil(21 / (5 x 3.04620 / 1)) = ceil(21 / 15.23) = 2.
  const deploy::BlindMemory memory =
      deploy::blind_memory(coverage_with_gap(100, 140, 0.5, 3.0), 1.0, 0.25, 5.0);
  REQUIRE(memory.gaps.size() == 1);
  CHECK(memory.gaps[0].keep_distance == Approx(0.50771).epsilon(1e-4));
  CHECK(memory.gaps[0].seen_distance == Approx(3.04620).epsilon(1e-4));
  CHECK_FALSE(memory.gaps[0].reaches_back);
  CHECK(memory.hit.hit_max == 21);
  CHECK(memory.hit.hit == 2);
  // nav2's persistence keeps the same 21 updates: 21 / 5 Hz = 4.2 s; the obstacle is seen
  // last at 99 deg, the azimuth before the gap on the left.
  CHECK(memory.persistence == Approx(4.2));
  CHECK(memory.gaps[0].persistence == Approx(4.2));
  CHECK(memory.gaps[0].last_seen == 99);
}

TEST_CASE("blind memory: a gap on the right, and one reaching the back", "[deploy]") {
  // Gap 200..260 deg: the right side, -160..-100 deg. Driving forward, a grazing obstacle on
  // the right enters at -100 deg (x = 0.4 cot 100 deg = -0.07053 m) and leaves at -160 deg
  // (x = 0.4 cot 160 deg = -1.09899 m): kept 1.02846 m;
  // hit_max = ceil(2 x 5 x 1.02846 / 0.25) = ceil(41.14) = 42.
  const deploy::BlindMemory right =
      deploy::blind_memory(coverage_with_gap(200, 260, 0.4, 2.0), 1.0, 0.25, 5.0);
  REQUIRE(right.gaps.size() == 1);
  CHECK(right.gaps[0].keep_distance == Approx(1.02846).epsilon(1e-4));
  CHECK(right.hit.hit_max == 42);
  CHECK(right.persistence == Approx(42 / 5.0));
  // On the right it enters at 260 deg (-100) coming from 261 deg, where it is seen last.
  CHECK(right.gaps[0].last_seen == 261);
  // Gap 120..180 deg: an obstacle entering at 120 deg (x = 0.4 cot 120 deg = -0.23094 m) is
  // never seen again and is kept until the body has passed it (x = -0.4 m): 0.16906 m.
  const deploy::BlindMemory back =
      deploy::blind_memory(coverage_with_gap(120, 180, 0.4, 2.0), 1.0, 0.25, 5.0);
  REQUIRE(back.gaps.size() == 1);
  CHECK(back.gaps[0].reaches_back);
  CHECK(back.gaps[0].keep_distance == Approx(0.16906).epsilon(1e-4));
}

TEST_CASE("blind memory: a gap straight astern is not passed driving forward", "[deploy]") {
  const deploy::BlindMemory astern =
      deploy::blind_memory(coverage_with_gap(150, 210, 0.4, 2.0), 1.0, 0.25, 5.0);
  CHECK(astern.gaps.empty());
  CHECK(astern.hit.hit_max == costmap::HitLayerParams{}.hit_max);
}
