#include "rigdesign/model/statistics.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace rigdesign;

TEST_CASE("median: the middle value, or the mean of the two middle values", "[model]") {
  CHECK(model::median(std::vector<double>{5.0, 1.0, 3.0}) == 3.0);
  // Sorted 1 2 3 4: (2 + 3) / 2.
  CHECK(model::median(std::vector<double>{4.0, 1.0, 3.0, 2.0}) == 2.5);
  CHECK(model::median(std::vector<double>{7.0}) == 7.0);
  CHECK(std::isnan(model::median(std::vector<double>{})));
}

TEST_CASE("percentile: nearest rank, the ceil(share n)-th smallest", "[model]") {
  const std::vector<double> samples{50.0, 10.0, 40.0, 20.0, 30.0};
  CHECK(model::percentile(samples, 0.95) == 50.0);  // ceil(4.75) = 5th
  CHECK(model::percentile(samples, 0.5) == 30.0);   // ceil(2.5) = 3rd
  CHECK(model::percentile(samples, 0.1) == 10.0);   // ceil(0.5) = 1st
  CHECK(model::percentile(samples, 0.4) == 20.0);   // ceil(2.0) = 2nd, not the 3rd
  CHECK(model::percentile(samples, 1.0) == 50.0);
  // The 50th percentile of an even count is the lower middle value, unlike the median.
  CHECK(model::percentile(std::vector<double>{4.0, 1.0, 3.0, 2.0}, 0.5) == 2.0);
  CHECK(std::isnan(model::percentile(std::vector<double>{}, 0.5)));
}

TEST_CASE("statistics leave their input as it was", "[model]") {
  const std::vector<double> samples{3.0, 1.0, 2.0, 5.0, 4.0, 0.0};
  const std::vector<double> copy = samples;
  CHECK(model::median(samples) == 2.5);
  CHECK(model::percentile(samples, 0.99) == 5.0);
  CHECK(samples == copy);
}
