// The one tick rule every chart uses, against steps worked out by hand: span / count rounded to
// 1, 2 or 5 (or the given factors) times a power of ten, and ticks that include a range's end.
#include "render/chart_axes.hpp"

#include <catch2/catch.hpp>

using namespace rigdesign;

TEST_CASE("chart axes: round tick steps", "[render]") {
  using render::StepRounding;
  CHECK(render::tick_step(10, 5, StepRounding::up) == Approx(2.0));        // 2 is round already
  CHECK(render::tick_step(7, 5, StepRounding::up) == Approx(2.0));         // 1.4 -> 2
  CHECK(render::tick_step(7, 5, StepRounding::down) == Approx(1.0));       // 1.4 -> 1
  CHECK(render::tick_step(0.037, 4, StepRounding::up) == Approx(0.01));    // 0.00925 -> 0.01
  CHECK(render::tick_step(3000, 4, StepRounding::down) == Approx(500.0));  // 750 -> 500
  const double quarters[] = {1.0, 2.5, 5.0};
  CHECK(render::tick_step(12, 5, StepRounding::up, quarters) == Approx(2.5));  // 2.4 -> 2.5
  CHECK(render::tick_step(0, 5, StepRounding::up) > 0.0);  // an empty span stays finite
}

TEST_CASE("chart axes: tick values from the first multiple to the end", "[render]") {
  const std::vector<double> halves = render::tick_values(0.3, 2.0, 0.5);
  REQUIRE(halves.size() == 4);
  CHECK(halves.front() == Approx(0.5));
  CHECK(halves.back() == Approx(2.0));
  // 0.1 + 0.1 + 0.1 is 0.30000000000000004: still the tick at the range's end 0.3.
  CHECK(render::tick_values(0.0, 0.3, 0.1).size() == 4);
  CHECK(render::tick_values(-1.0, 1.0, 1.0) == std::vector<double>{-1.0, 0.0, 1.0});
}
