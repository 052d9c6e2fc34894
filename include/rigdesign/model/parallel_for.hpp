#pragma once
/// Independent jobs on a few threads: body(i) for every i in [0, count), each index taken from
/// a shared counter (a thread slowed by other work on its core takes fewer), the calling thread
/// one of the workers. Results must go to per-index slots, so they never depend on which thread
/// ran what. The first exception a job throws is rethrown once every thread has stopped.
#include <cstddef>
#include <functional>

namespace rigdesign::model {

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& body);

}  // namespace rigdesign::model
