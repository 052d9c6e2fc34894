#pragma once
// How the PCL peer's OpenMP regions run, switchable per call inside one process.
//
// Why: PCL's FLANN search opens an OpenMP parallel region for every nearest-neighbour query,
// even with one thread, and libgomp's team start and end cost microseconds of futex calls per
// region. Timing PCL as shipped then measures that per-query threading on the machine at hand,
// not the algorithm. The bench executable defines GOMP_parallel itself, so PCL's calls bind to
// it (an executable's definitions come first in the dynamic linker's search): in `shipped`
// mode it forwards to libgomp's; in `inline_serial` mode it runs the region's body once on the
// calling thread, as a serial OpenMP runtime would. Worksharing and barriers inside such a
// region find no team and libgomp runs them serially, as OpenMP allows for orphaned constructs.
#include <cstdint>

namespace rigdesign::bench {

enum class OpenMpRegions { shipped, inline_serial };

void set_openmp_regions(OpenMpRegions mode);

/// Parallel regions entered since the start of the process, in either mode.
std::uint64_t openmp_regions_entered();

}  // namespace rigdesign::bench
