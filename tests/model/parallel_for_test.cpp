// model::parallel_for: every index runs exactly once whatever the thread count, and a job's
// exception reaches the caller.
#include "rigdesign/model/parallel_for.hpp"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <vector>

using namespace rigdesign;

TEST_CASE("parallel_for runs every index once", "[model]") {
  for (const int threads : {1, 2, 5}) {
    for (const std::size_t count :
         {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{100}}) {
      std::vector<int> runs(count, 0);
      model::parallel_for(count, threads, [&](std::size_t i) { ++runs[i]; });
      CHECK(runs == std::vector<int>(count, 1));
    }
  }
}

TEST_CASE("parallel_for rethrows a job's exception", "[model]") {
  CHECK_THROWS_AS(model::parallel_for(10, 2,
                                      [](std::size_t i) {
                                        if (i == 7) throw std::runtime_error("job 7");
                                      }),
                  std::runtime_error);
}
