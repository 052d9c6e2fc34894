#include "openmp_regions.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace rigdesign::bench {
namespace {

using RegionBody = void (*)(void*);
using GompParallel = void (*)(RegionBody, void*, unsigned, unsigned);

OpenMpRegions mode = OpenMpRegions::shipped;
std::uint64_t regions = 0;

/// libgomp's own entry point (GOMP_parallel has been versioned GOMP_4.0 since GCC 4.9).
GompParallel libgomp_parallel() {
  static const GompParallel real = [] {
    void* symbol = dlvsym(RTLD_NEXT, "GOMP_parallel", "GOMP_4.0");
    if (symbol == nullptr) symbol = dlsym(RTLD_NEXT, "GOMP_parallel");
    if (symbol == nullptr) {
      std::fprintf(stderr, "openmp_regions: libgomp's GOMP_parallel not found: %s\n", dlerror());
      std::abort();
    }
    return reinterpret_cast<GompParallel>(symbol);
  }();
  return real;
}

}  // namespace

void set_openmp_regions(OpenMpRegions regions_mode) {
  mode = regions_mode;
}

std::uint64_t openmp_regions_entered() {
  return regions;
}

}  // namespace rigdesign::bench

// GCC lowers `#pragma omp parallel` to this call; see openmp_regions.hpp for why it is
// defined here.
extern "C" void GOMP_parallel(void (*body)(void*), void* data, unsigned num_threads,
                              unsigned flags) {
  using namespace rigdesign::bench;
  ++regions;
  if (mode == OpenMpRegions::inline_serial) {
    body(data);
    return;
  }
  libgomp_parallel()(body, data, num_threads, flags);
}
