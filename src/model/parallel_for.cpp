#include "rigdesign/model/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rigdesign::model {

void parallel_for_chunks(std::size_t count, std::size_t chunk, int threads,
                         const std::function<void(std::size_t, std::size_t, int)>& body) {
  const std::size_t step = std::max<std::size_t>(1, chunk);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&](int worker) {
    while (!failed) {
      const std::size_t begin = next.fetch_add(step);
      if (begin >= count) return;
      try {
        body(begin, std::min(count, begin + step), worker);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;  // the others stop after their current chunk
      }
    }
  };
  const std::size_t chunks = count / step + (count % step != 0 ? 1 : 0);
  const std::size_t workers = std::min(chunks, static_cast<std::size_t>(std::max(1, threads)));
  std::vector<std::thread> helpers;
  for (std::size_t t = 1; t < workers; ++t) helpers.emplace_back(work, static_cast<int>(t));
  work(0);
  for (std::thread& helper : helpers) helper.join();
  if (error) std::rethrow_exception(error);
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body) {
  parallel_for_chunks(count, 1, threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

}  // namespace rigdesign::model
