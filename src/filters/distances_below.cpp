#include "filters/distances_below.hpp"

#include <array>
#include <cstdint>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RIGDESIGN_DISTANCES_AVX2 1
#include <immintrin.h>
#endif

namespace rigdesign::filters {
namespace {

std::size_t portable(const float* xs, const float* ys, const float* zs, const IndexRun* runs,
                     std::size_t count, float px, float py, float pz, float bound, float* out) {
  std::size_t kept = 0;
  for (std::size_t r = 0; r < count; ++r) {
    for (std::uint32_t i = runs[r].begin; i < runs[r].end; ++i) {
      // Branch-free: every value written, only the kept advance.
      const float dx = xs[i] - px, dy = ys[i] - py, dz = zs[i] - pz;
      const float squared = dx * dx + dy * dy + dz * dz;
      out[kept] = squared;
      kept += squared < bound ? 1 : 0;
    }
  }
  return kept;
}

#if defined(RIGDESIGN_DISTANCES_AVX2)

/// For each 8-bit mask of lanes kept, the lane indices that move the kept lanes to the front.
constexpr std::array<std::array<std::int32_t, 8>, 256> make_compaction_table() {
  std::array<std::array<std::int32_t, 8>, 256> table{};
  for (int mask = 0; mask < 256; ++mask) {
    int next = 0;
    for (int lane = 0; lane < 8; ++lane) {
      if ((mask >> lane) & 1) table[mask][next++] = lane;
    }
    for (; next < 8; ++next) table[mask][next] = 0;
  }
  return table;
}

alignas(32) constexpr std::array<std::array<std::int32_t, 8>, 256> kCompaction =
    make_compaction_table();

__attribute__((target("avx2,popcnt"))) std::size_t avx2(const float* all_xs, const float* all_ys,
                                                        const float* all_zs, const IndexRun* runs,
                                                        std::size_t count, float px, float py,
                                                        float pz, float bound, float* out) {
  const __m256 x = _mm256_set1_ps(px), y = _mm256_set1_ps(py), z = _mm256_set1_ps(pz);
  const __m256 limit = _mm256_set1_ps(bound);
  const __m256 infinity = _mm256_set1_ps(__builtin_inff());
  std::size_t kept = 0;
  for (std::size_t r = 0; r < count; ++r) {
    const float* xs = all_xs + runs[r].begin;
    const float* ys = all_ys + runs[r].begin;
    const float* zs = all_zs + runs[r].begin;
    const std::size_t n = runs[r].end - runs[r].begin;
    for (std::size_t i = 0; i < n; i += 8) {
      __m256 dx, dy, dz;
      __m256 inside = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
      if (i + 8 <= n) {
        dx = _mm256_sub_ps(_mm256_loadu_ps(xs + i), x);
        dy = _mm256_sub_ps(_mm256_loadu_ps(ys + i), y);
        dz = _mm256_sub_ps(_mm256_loadu_ps(zs + i), z);
      } else {  // the last lanes: loaded under a mask (nothing read past the end), then dropped
        const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
        const __m256i load =
            _mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<std::int32_t>(n - i)), lanes);
        dx = _mm256_sub_ps(_mm256_maskload_ps(xs + i, load), x);
        dy = _mm256_sub_ps(_mm256_maskload_ps(ys + i, load), y);
        dz = _mm256_sub_ps(_mm256_maskload_ps(zs + i, load), z);
        inside = _mm256_castsi256_ps(load);
      }
      // (dx*dx + dy*dy) + dz*dz, as the portable loop, no fused multiply-add.
      __m256 squared = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)),
                                     _mm256_mul_ps(dz, dz));
      squared = _mm256_blendv_ps(infinity, squared, inside);  // lanes past the end: +inf
      const int mask = _mm256_movemask_ps(_mm256_cmp_ps(squared, limit, _CMP_LT_OQ));
      const __m256i order = _mm256_load_si256(
          reinterpret_cast<const __m256i*>(kCompaction[static_cast<std::size_t>(mask)].data()));
      _mm256_storeu_ps(out + kept, _mm256_permutevar8x32_ps(squared, order));
      kept += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(mask)));
    }
  }
  return kept;
}

#endif

using Implementation = std::size_t (*)(const float*, const float*, const float*, const IndexRun*,
                                       std::size_t, float, float, float, float, float*);

Implementation chosen() {
#if defined(RIGDESIGN_DISTANCES_AVX2)
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt")) return avx2;
#endif
  return portable;
}

Implementation implementation() {
  static const Implementation chosen_once = chosen();
  return chosen_once;
}

}  // namespace

std::size_t append_distances_below(const float* xs, const float* ys, const float* zs,
                                   const IndexRun* runs, std::size_t count, float px, float py,
                                   float pz, float bound, float* out) {
  return implementation()(xs, ys, zs, runs, count, px, py, pz, bound, out);
}

bool distances_below_use_avx2() {
  return implementation() != portable;
}

std::size_t append_distances_below_portable(const float* xs, const float* ys, const float* zs,
                                            const IndexRun* runs, std::size_t count, float px,
                                            float py, float pz, float bound, float* out) {
  return portable(xs, ys, zs, runs, count, px, py, pz, bound, out);
}

std::size_t append_distances_below_avx2(const float* xs, const float* ys, const float* zs,
                                        const IndexRun* runs, std::size_t count, float px, float py,
                                        float pz, float bound, float* out) {
#if defined(RIGDESIGN_DISTANCES_AVX2)
  return avx2(xs, ys, zs, runs, count, px, py, pz, bound, out);
#else
  return portable(xs, ys, zs, runs, count, px, py, pz, bound, out);
#endif
}

}  // namespace rigdesign::filters
