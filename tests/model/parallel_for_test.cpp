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

TEST_CASE("parallel_for_chunks covers every index once in whole chunks", "[model]") {
  for (const int threads : {1, 2, 5}) {
    for (const std::size_t chunk : {std::size_t{0}, std::size_t{1}, std::size_t{4}}) {
      const std::size_t count = 10;
      std::vector<int> runs(count, 0);
      std::vector<int> worker_of(count, -1);
      model::parallel_for_chunks(count, chunk, threads,
                                 [&](std::size_t begin, std::size_t end, int worker) {
                                   for (std::size_t i = begin; i < end; ++i) {
                                     ++runs[i];
                                     worker_of[i] = worker;
                                   }
                                 });
      CHECK(runs == std::vector<int>(count, 1));
      const std::size_t step = chunk == 0 ? 1 : chunk;
      for (std::size_t i = 0; i < count; ++i) {
        CHECK(worker_of[i] >= 0);
        CHECK(worker_of[i] < threads);
        // Indices of one chunk (4 by 4: 0-3, 4-7, 8-9) ran on one thread.
        CHECK(worker_of[i] == worker_of[i - i % step]);
      }
    }
  }
}
