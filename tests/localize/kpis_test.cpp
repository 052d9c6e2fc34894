#include "rigdesign/localize/kpis.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace rigdesign;

TEST_CASE(
    "Algorithm 1: C is the first measurement count whose estimate is within the acceptable error",
    "[localize]") {
  const std::vector<std::pair<int, double>> sequence = {
      {10, 12.0}, {20, 6.0}, {30, 4.0}, {40, 7.0}, {50, 3.0}};
  CHECK(localize::data_amount(sequence, 5.0) == 30);
  CHECK(localize::data_amount(sequence, 6.0) == 20);  // within means <=
  CHECK(localize::data_amount(sequence, 2.0) == std::nullopt);
  CHECK(localize::data_amount({}, 5.0) == std::nullopt);
}

TEST_CASE("error statistics: smallest, mean, median and RMS", "[localize]") {
  const localize::ErrorStats stats = localize::error_stats({4.0, 3.0});
  CHECK(stats.count == 2);
  CHECK(stats.smallest == 3.0);
  CHECK(stats.mean == Approx(3.5));
  CHECK(stats.median == Approx(3.5));
  CHECK(stats.rms == Approx(std::sqrt(12.5)));
  CHECK(localize::error_stats({1.0, 9.0, 2.0}).median == 2.0);
  CHECK(localize::error_stats({}).count == 0);
}

TEST_CASE("position error is horizontal when z is unobservable", "[localize]") {
  CHECK(localize::position_error({3, 4, 10}, {0, 0, 0}, 2) == Approx(5.0));
  CHECK(localize::position_error({3, 4, 12}, {0, 0, 0}, 3) == Approx(13.0));
}
