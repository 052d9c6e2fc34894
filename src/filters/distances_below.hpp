#pragma once
// The squared distances from one point to a run of structure-of-arrays points, keeping only
// those below a bound: the inner loop of the neighbour search. Private to filters.
//
// Two versions, one result: AVX2 (8 lanes, compaction by a permutation table) where the CPU
// has it, chosen once at run time so one binary runs on any x86-64; a portable loop elsewhere.
// Both compute dx*dx + dy*dy + dz*dz in the same order without fused multiply-add, so every
// distance, and therefore every filter output, is the same bit for bit on every machine.
#include <cstddef>
#include <cstdint>

namespace rigdesign::filters {

/// A run [begin, end) of point indices.
struct IndexRun {
  std::uint32_t begin;
  std::uint32_t end;
};

/// Appends to `out` the squared distances from (px, py, pz) to the points
/// (xs[i], ys[i], zs[i]), i in each of runs[0, count), that are below `bound`, in order;
/// returns how many. `out` must have room for every run's points + 8 floats (the vector
/// version stores whole lanes). One call per query: the version is chosen once per call and
/// the runs (one per row of grid cells) go through one loop.
std::size_t append_distances_below(const float* xs, const float* ys, const float* zs,
                                   const IndexRun* runs, std::size_t count, float px, float py,
                                   float pz, float bound, float* out);

/// Whether the AVX2 version is in use on this CPU.
bool distances_below_use_avx2();

/// The two versions by name, for the test that holds them to one result. The AVX2 one may be
/// called only where distances_below_use_avx2() says so.
std::size_t append_distances_below_portable(const float* xs, const float* ys, const float* zs,
                                            const IndexRun* runs, std::size_t count, float px,
                                            float py, float pz, float bound, float* out);
std::size_t append_distances_below_avx2(const float* xs, const float* ys, const float* zs,
                                        const IndexRun* runs, std::size_t count, float px, float py,
                                        float pz, float bound, float* out);

}  // namespace rigdesign::filters
