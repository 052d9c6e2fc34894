#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/costmap/inflation_layer.hpp"

using namespace rigdesign;

TEST_CASE("inflation costs follow nav2's values", "[costmap]") {
  costmap::InflationParams params;  // inscribed 0.1 m, radius 0.55 m, k = 3 / m
  CHECK(costmap::inflation_cost(0.0, params) == 254);
  CHECK(costmap::inflation_cost(0.05, params) == 253);
  CHECK(costmap::inflation_cost(0.1, params) == 253);
  // 252 exp(-3 (0.2 - 0.1)) = 186.69 -> 186; 252 exp(-3 x 0.45) = 65.33 -> 65.
  CHECK(costmap::inflation_cost(0.2, params) == 186);
  CHECK(costmap::inflation_cost(0.55, params) == 65);
  CHECK(costmap::inflation_cost(0.56, params) == 0);
}

TEST_CASE("the inflation layer decays around a lethal cell", "[costmap]") {
  costmap::GridWindow window;
  window.width = 21;
  window.height = 21;
  window.resolution = 0.05;
  costmap::CostGrid master(window, costmap::cost::kFree);
  master.at(10, 10) = costmap::cost::kLethal;
  master.at(10, 13) = costmap::cost::kUnknown;  // 0.15 m away: 216 < 253, stays unknown
  master.at(11, 10) = costmap::cost::kUnknown;  // 0.05 m away: inscribed, takes 253
  costmap::InflationLayer inflation;
  inflation.apply(master);
  CHECK(master.at(10, 10) == 254);
  CHECK(master.at(12, 10) == 253);  // 0.10 m
  CHECK(master.at(11, 11) == 253);  // 0.0707 m
  CHECK(master.at(13, 10) == 216);  // 252 exp(-0.15) = 216.9
  CHECK(master.at(13, 14) == 160);  // 5 cells = 0.25 m: 252 exp(-0.45) = 160.7
  CHECK(master.at(20, 10) == 75);   // 0.50 m: 252 exp(-1.2) = 75.9
  CHECK(master.at(20, 20) == 0);    // 0.707 m, beyond 0.55 m
  CHECK(master.at(10, 13) == costmap::cost::kUnknown);
  CHECK(master.at(11, 10) == costmap::cost::kInscribed);
}

TEST_CASE("the distance transform matches a brute-force nearest source", "[costmap]") {
  const int width = 31;
  const int height = 17;
  std::mt19937_64 rng(3);
  std::bernoulli_distribution source(0.02);
  std::vector<std::uint8_t> mask(width * height);
  for (auto& m : mask) m = source(rng);
  mask[0] = 0;
  std::vector<double> fast;
  costmap::squared_distance_transform(mask, width, height, fast);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double best = 1e300;
      for (int sy = 0; sy < height; ++sy) {
        for (int sx = 0; sx < width; ++sx) {
          if (mask[sy * width + sx])
            best = std::min(best, double((x - sx) * (x - sx) + (y - sy) * (y - sy)));
        }
      }
      CHECK(fast[y * width + x] == best);
    }
  }
  // No source at all: everything is "far".
  std::vector<std::uint8_t> empty(12, 0);
  costmap::squared_distance_transform(empty, 4, 3, fast);
  for (double d : fast) CHECK(d > 1e9);
}
