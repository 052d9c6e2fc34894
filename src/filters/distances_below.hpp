#pragma once
// The squared distances from one point to a run of structure-of-arrays points, keeping only
// those below a bound: the inner loop of the neighbour search. Private to filters.
//
// Two versions, one result: AVX2 (8 lanes, compaction by a permutation table) where the CPU
// has it, chosen once at run time so one binary runs on any x86-64; a portable loop elsewhere.
// Both compute dx*dx + dy*dy + dz*dz in the same order without fused multiply-add, so every
// distance, and therefore every filter output, is the same bit for bit on every machine.
#include <cstddef>

namespace rigdesign::filters {

/// Appends to `out` the squared distances from (px, py, pz) to the points
/// (xs[i], ys[i], zs[i]), i < n, that are below `bound`, in order; returns how many.
/// `out` must have room for n + 8 floats (the vector version stores whole lanes).
std::size_t append_distances_below(const float* xs, const float* ys, const float* zs,
                                   std::size_t n, float px, float py, float pz, float bound,
                                   float* out);

/// Whether the AVX2 version is in use on this CPU.
bool distances_below_use_avx2();

/// The two versions by name, for the test that holds them to one result. The AVX2 one may be
/// called only where distances_below_use_avx2() says so.
std::size_t append_distances_below_portable(const float* xs, const float* ys, const float* zs,
                                            std::size_t n, float px, float py, float pz,
                                            float bound, float* out);
std::size_t append_distances_below_avx2(const float* xs, const float* ys, const float* zs,
                                        std::size_t n, float px, float py, float pz, float bound,
                                        float* out);

}  // namespace rigdesign::filters
