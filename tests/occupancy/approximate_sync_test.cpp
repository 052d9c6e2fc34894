// Issue 54 item 2: the approximate-time set of periodic sensors, worked by hand.
#include "rigdesign/occupancy/approximate_sync.hpp"

#include <catch2/catch.hpp>

using namespace rigdesign;

TEST_CASE("a sensor's latest stamp at or before a time", "[occupancy]") {
  const occupancy::FrameClock clock{0.1, 0.03};
  CHECK(occupancy::latest_stamp(clock, 1.0) == Approx(0.93));
  CHECK(occupancy::latest_stamp(clock, 1.03) == Approx(1.03));  // a frame exactly at the tick
  CHECK(occupancy::latest_stamp(clock, 0.0) == Approx(-0.07));
}

TEST_CASE("the approximate-time set has the smallest spread ending by the tick", "[occupancy]") {
  // Two 10 Hz lidars at phases 0.01 and 0.09 and a 30 Hz camera at phase 0.
  // Tick 1.0. Sets ending at each sensor's latest frame:
  //   lidar A at 0.91: B's latest by then 0.89, camera 0.9: spread 0.02;
  //   lidar B at 0.99: A 0.91, camera 0.9667: spread 0.08;
  //   camera at 1.0: A 0.91, B 0.99: spread 0.09. The first wins.
  const std::vector<occupancy::FrameClock> clocks{{0.1, 0.01}, {0.1, 0.09}, {1.0 / 30, 0.0}};
  const std::vector<double> set = occupancy::approximate_time_set(clocks, 1.0);
  REQUIRE(set.size() == 3);
  CHECK(set[0] == Approx(0.91));
  CHECK(set[1] == Approx(0.89));
  CHECK(set[2] == Approx(0.9));
  // Sensors in phase: every frame at the tick, spread 0.
  const std::vector<occupancy::FrameClock> in_phase{{0.1, 0.0}, {0.1, 0.0}};
  CHECK(occupancy::approximate_time_set(in_phase, 2.0) == std::vector<double>{2.0, 2.0});
  CHECK_THROWS_AS(occupancy::approximate_time_set({}, 1.0), std::invalid_argument);
}

TEST_CASE("frame clocks: one period per frequency, a phase within it, fixed by the seed",
          "[occupancy]") {
  const std::vector<double> frequencies{10.0, 30.0};
  const std::vector<occupancy::FrameClock> a = occupancy::frame_clocks(frequencies, 7);
  const std::vector<occupancy::FrameClock> b = occupancy::frame_clocks(frequencies, 7);
  REQUIRE(a.size() == 2);
  CHECK(a[0].period == Approx(0.1));
  CHECK(a[1].period == Approx(1.0 / 30));
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].phase >= 0.0);
    CHECK(a[i].phase < a[i].period);
    CHECK(a[i].phase == b[i].phase);
  }
  const std::vector<double> none{0.0};
  CHECK_THROWS_AS(occupancy::frame_clocks(none, 7), std::invalid_argument);
}
