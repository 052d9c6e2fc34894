#include "rigdesign/filters/voxel_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::filters {
namespace {

constexpr int kKeyBits = 21;  // three axes packed in 63 bits
constexpr std::int64_t kMaxCells = std::int64_t{1} << kKeyBits;

struct Accumulator {
  std::uint64_t key = 0;
  float x = 0, y = 0, z = 0;  // float sums, as PCL accumulates them
  std::uint32_t count = 0;    // 0 marks an empty slot
};

/// The hash table's memory, kept by each thread from call to call. Every slot is empty between
/// calls (SlotsCleared empties the used ones on the way out, whatever happens), so a call
/// clears nothing up front.
struct VoxelScratch {
  std::vector<Accumulator> table, spare;
  std::vector<std::uint32_t> occupied;  // the used slots of `table`, in first-seen order
  std::size_t last_voxels = 0;          // the previous call's voxel count

  /// The first `n` slots of the table, grown (with empty slots) when needed.
  Accumulator* slots(std::size_t n) {
    if (table.size() < n) table.resize(n);
    return table.data();
  }
  Accumulator* spare_slots(std::size_t n) {
    if (spare.size() < n) spare.resize(n);
    return spare.data();
  }
  /// The spare, filled by a grow, becomes the table; the emptied table the spare.
  Accumulator* swap_slots() {
    table.swap(spare);
    return table.data();
  }
};

struct SlotsCleared {
  VoxelScratch& scratch;
  ~SlotsCleared() {
    for (const std::uint32_t slot : scratch.occupied) scratch.table[slot] = Accumulator{};
    scratch.occupied.clear();
  }
};

/// Spreads packed keys over the table: the high half folded into the low one, then one
/// multiply by 2^64 / golden ratio; callers take the product's high bits.
std::uint64_t mix(std::uint64_t key) {
  return (key ^ (key >> 31)) * 0x9e3779b97f4a7c15ULL;
}

/// A point's x, y, z and whatever follows it in memory (the next point's x), as four lanes
/// Eigen vectorises (SSE2, NEON). Never called on a cloud's last point, whose fourth lane
/// would lie past the end; the fourth lane is ignored.
Eigen::Array4f four_lanes(const model::Point3f& p) {
  return Eigen::Map<const Eigen::Array4f>(p.data());
}

/// Three 21-bit voxel indices, floor((lanes - offset) * inverse) - first, packed in a key.
/// floor() as truncation plus a correction, in SSE2 where there is SSE2 (floorf needs SSE 4.1
/// to be inlined and would cost a call per coordinate).
std::uint64_t voxel_key(const Eigen::Array4f& lanes, const Eigen::Array4f& offset, float inverse,
                        const Eigen::Array4i& first) {
  alignas(16) std::int32_t index[4];
#if defined(__SSE2__)
  const __m128 scaled = _mm_mul_ps(
      _mm_sub_ps(_mm_loadu_ps(lanes.data()), _mm_loadu_ps(offset.data())), _mm_set1_ps(inverse));
  const __m128i truncated = _mm_cvttps_epi32(scaled);
  const __m128i below =
      _mm_castps_si128(_mm_cmplt_ps(scaled, _mm_cvtepi32_ps(truncated)));  // -1 or 0
  const __m128i floored = _mm_add_epi32(truncated, below);
  _mm_store_si128(
      reinterpret_cast<__m128i*>(index),
      _mm_sub_epi32(floored, _mm_loadu_si128(reinterpret_cast<const __m128i*>(first.data()))));
#else
  const Eigen::Array4f scaled = (lanes - offset) * inverse;
  for (int axis = 0; axis < 3; ++axis) {
    index[axis] = static_cast<std::int32_t>(std::floor(scaled[axis])) - first[axis];
  }
#endif
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(index[0])) |
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(index[1])) << kKeyBits) |
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(index[2])) << (2 * kKeyBits));
}

/// Lowest and highest coordinate per axis.
std::pair<Eigen::Array3f, Eigen::Array3f> bounding_box(const std::vector<model::Point3f>& points) {
  Eigen::Array4f low = Eigen::Array4f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Array4f high = -low;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Eigen::Array4f lanes = four_lanes(points[i]);
    low = low.min(lanes);
    high = high.max(lanes);
  }
  const Eigen::Array3f last = points.back().array();
  return {low.head<3>().min(last), high.head<3>().max(last)};
}

}  // namespace

model::PointCloud voxel_grid(const model::PointCloud& cloud, const model::VoxelGridParams& params) {
  if (!(params.leaf > 0) || !std::isfinite(params.leaf)) {
    throw model::InputError(model::Diagnostic{{},
                                              "voxel_grid.leaf",
                                              "is " + model::format_number(params.leaf),
                                              "a voxel size in metres, > 0"});
  }
  model::PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  if (cloud.empty()) return result;
  // Voxel indices as PCL computes them, in float: floor((p - offset) * (1 / leaf)), so a
  // point on a voxel boundary lands where PCL puts it and the outputs compare one to one.
  const float inverse = 1.0f / static_cast<float>(params.leaf);
  const Eigen::Array3f offset = params.grid_offset.cast<float>().array();
  const auto [low, high] = bounding_box(cloud.points);
  // PCL's voxel index, floor((p - offset) * inverse) in float, minus the lowest index.
  // The fourth lane holds an x (the next point's) and is offset like x, so it stays in range.
  const Eigen::Array4f offset4(offset.x(), offset.y(), offset.z(), offset.x());
  const auto scaled = [&](const Eigen::Array4f& lanes) { return (lanes - offset4) * inverse; };
  const Eigen::Array4f lowest = scaled(Eigen::Array4f(low.x(), low.y(), low.z(), low.x())).floor();
  const Eigen::Array4f highest =
      scaled(Eigen::Array4f(high.x(), high.y(), high.z(), high.x())).floor();
  const Eigen::Array3d first = lowest.head<3>().cast<double>();
  const Eigen::Array3d last = highest.head<3>().cast<double>();
  if (((last - first) >= static_cast<double>(kMaxCells - 1)).any()) {
    throw model::InputError(model::Diagnostic{
        {},
        "voxel_grid.leaf",
        "is too small for the cloud's extent: more than 2^21 voxels "
        "along an axis would overflow the voxel index",
        "a leaf of at least " +
            model::format_number(
                static_cast<double>((high - low).maxCoeff()) / static_cast<double>(kMaxCells - 2),
                3) +
            " m"});
  }
  // Indices are taken in 32-bit lanes; a cloud whose indices leave that range (a small leaf
  // millions of metres from the origin) is refused rather than wrapped.
  constexpr double kLaneLimit = 2147483520.0;  // the largest float below 2^31
  if ((first.abs() >= kLaneLimit).any() || (last.abs() >= kLaneLimit).any()) {
    throw model::InputError(
        model::Diagnostic{{},
                          "voxel_grid.leaf",
                          "puts voxel indices beyond 2^31 (the cloud lies too far from the "
                          "grid's origin for this leaf)",
                          "a larger leaf, or a cloud nearer the origin"});
  }
  const Eigen::Array4i first4 = lowest.cast<int>();
  // Open addressing on the packed voxel key, sums accumulated in place, in a table that lives
  // from call to call on each thread (a per-frame filter allocates nothing, and a table larger
  // than glibc's mmap threshold is not handed back and faulted in again on every call). It is
  // sized from the previous call's voxel count (frames alike), or on a first call from a quarter
  // of the points (clouds shrink about tenfold at 3 cm), at most twice the voxels the bounding
  // box holds, and doubles when half full.
  thread_local VoxelScratch scratch;
  const SlotsCleared cleanup{scratch};
  const Eigen::Array3d spans = last - first + 1.0;
  const double box_voxels = spans.x() * spans.y() * spans.z();
  const double guess = scratch.last_voxels > 0 ? static_cast<double>(scratch.last_voxels)
                                               : static_cast<double>(cloud.size()) / 4;
  const double expected = std::min(guess, box_voxels);
  int bits = 10;
  while (static_cast<double>(std::size_t{1} << bits) < 2 * expected && bits < 24) ++bits;
  Accumulator* table = scratch.slots(std::size_t{1} << bits);
  std::vector<std::uint32_t>& occupied = scratch.occupied;
  const auto home = [&](std::uint64_t key) {
    return static_cast<std::size_t>(mix(key) >> (64 - bits));
  };
  const auto find = [&](std::uint64_t key) {
    const std::size_t mask = (std::size_t{1} << bits) - 1;
    std::size_t slot = home(key);
    while (table[slot].count != 0 && table[slot].key != key) slot = (slot + 1) & mask;
    return slot;
  };
  const auto grow = [&] {
    ++bits;
    Accumulator* bigger = scratch.spare_slots(std::size_t{1} << bits);
    const std::size_t mask = (std::size_t{1} << bits) - 1;
    for (std::uint32_t& slot : occupied) {
      std::size_t moved = home(table[slot].key);
      while (bigger[moved].count != 0) moved = (moved + 1) & mask;
      bigger[moved] = table[slot];
      table[slot] = Accumulator{};
      slot = static_cast<std::uint32_t>(moved);
    }
    table = scratch.swap_slots();
  };
  // A point's key is computed a few points ahead of its turn, in a small ring, so the table
  // slot it will touch can be prefetched: the table is larger than the cache and a miss costs
  // more than the rest of the work. Consecutive points of a scan mostly share a voxel: the
  // last voxel is kept at hand and the table is not searched for them.
  constexpr std::size_t kAhead = 16;  // a power of two
  const std::size_t points = cloud.size();
  const auto key_at = [&](std::size_t i) {
    const model::Point3f& p = cloud.points[i];
    return voxel_key(i + 1 < points ? four_lanes(p) : Eigen::Array4f(p.x(), p.y(), p.z(), p.x()),
                     offset4, inverse, first4);
  };
  std::uint64_t ahead[kAhead];
  for (std::size_t i = 0; i < std::min(kAhead, points); ++i) ahead[i] = key_at(i);
  std::uint64_t last_key = 0;
  Accumulator* voxel = nullptr;
  for (std::size_t i = 0; i < points; ++i) {
    const std::uint64_t key = ahead[i % kAhead];
    if (i + kAhead < points) {
      ahead[i % kAhead] = key_at(i + kAhead);
      __builtin_prefetch(&table[home(ahead[i % kAhead])], 1);
    }
    if (voxel == nullptr || key != last_key) {
      std::size_t slot = find(key);
      if (table[slot].count == 0) {  // a new voxel: the table doubles first if half full
        if ((occupied.size() + 1) * 2 > (std::size_t{1} << bits)) {
          grow();
          slot = find(key);
        }
        table[slot].key = key;
        occupied.push_back(static_cast<std::uint32_t>(slot));
      }
      voxel = &table[slot];
      last_key = key;
    }
    const model::Point3f& p = cloud.points[i];
    voxel->x += p.x();
    voxel->y += p.y();
    voxel->z += p.z();
    ++voxel->count;
  }
  result.points.reserve(occupied.size());
  for (const std::uint32_t filled : occupied) {
    const Accumulator& sums = table[filled];
    const float n = static_cast<float>(sums.count);
    result.points.emplace_back(sums.x / n, sums.y / n, sums.z / n);
  }
  scratch.last_voxels = occupied.size();
  return result;
}

}  // namespace rigdesign::filters
