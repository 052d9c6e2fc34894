#pragma once
/// Independent jobs on a few threads, the project's one thread pool: every index in
/// [0, count) is run once, chunks of indices taken from a shared counter (a thread slowed by
/// other work on its core takes fewer), the calling thread one of the workers. Results must go
/// to per-index slots, so they never depend on which thread ran what. The first exception a
/// job throws is rethrown once every thread has stopped; the others stop after their chunk.
#include <cstddef>
#include <functional>

namespace rigdesign::model {

/// body(i) for every i in [0, count) on at most `threads` threads (fewer than 1 means 1).
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

/// body(begin, end, worker) for consecutive chunks [begin, end) of at most `chunk` indices
/// (0 means 1); `worker` in [0, threads) names the thread, for per-thread scratch space
/// (the calling thread is worker 0). Chunks keep neighbouring indices on one thread.
void parallel_for_chunks(std::size_t count, std::size_t chunk, int threads,
                         const std::function<void(std::size_t, std::size_t, int)>& body);

}  // namespace rigdesign::model
