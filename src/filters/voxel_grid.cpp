#include "rigdesign/filters/voxel_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "rigdesign/io/input_error.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign {
namespace {

constexpr int kKeyBits = 21;  // three axes packed in 63 bits
constexpr std::int64_t kMaxCells = std::int64_t{1} << kKeyBits;

struct Accumulator {
  std::uint64_t key = 0;
  float x = 0, y = 0, z = 0;  // float sums, as PCL accumulates them
  std::uint32_t count = 0;    // 0 marks an empty slot
};

std::uint64_t mix(std::uint64_t key) {  // splitmix64 finaliser: spreads packed keys
  key ^= key >> 30;
  key *= 0xbf58476d1ce4e5b9ULL;
  key ^= key >> 27;
  key *= 0x94d049bb133111ebULL;
  return key ^ (key >> 31);
}

}  // namespace

PointCloud voxel_grid(const PointCloud& cloud, const VoxelGridParams& params) {
  if (!(params.leaf > 0) || !std::isfinite(params.leaf)) {
    throw InputError(Diagnostic{{}, "voxel_grid.leaf", "is " + format_number(params.leaf), "a voxel size in metres, > 0"});
  }
  PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  if (cloud.empty()) return result;
  // Voxel indices as PCL computes them, in float: floor((p - offset) * (1 / leaf)), so a
  // point on a voxel boundary lands where PCL puts it and the outputs compare one to one.
  const float inverse = 1.0f / static_cast<float>(params.leaf);
  const Eigen::Array3f offset = params.grid_offset.cast<float>().array();
  Eigen::Array3f low = Eigen::Array3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Array3f high = -low;
  for (const Point3f& p : cloud.points) {
    low = low.min(p.array());
    high = high.max(p.array());
  }
  const Eigen::Array3f first = ((low - offset) * inverse).floor();
  const Eigen::Array3f last = ((high - offset) * inverse).floor();
  if (((last - first).cast<double>() >= static_cast<double>(kMaxCells - 1)).any()) {
    throw InputError(Diagnostic{{}, "voxel_grid.leaf",
                                "is too small for the cloud's extent: more than 2^21 voxels "
                                "along an axis would overflow the voxel index",
                                "a leaf of at least " +
                                    format_number(static_cast<double>((high - low).maxCoeff()) /
                                                      static_cast<double>(kMaxCells - 2), 3) + " m"});
  }
  // Open addressing on the packed voxel key: one pass, sums accumulated in place. The table
  // starts at twice the voxels the bounding box can hold (if fewer than the points) and
  // doubles when half full, so a close-range cloud does not clear a table sized by points.
  const Eigen::Array3d spans = (last - first).cast<double>() + 1.0;
  const double box_voxels = spans.x() * spans.y() * spans.z();
  const double expected = std::min(static_cast<double>(cloud.size()), box_voxels);
  std::size_t capacity = 1024;
  while (static_cast<double>(capacity) < 2 * expected && capacity < (std::size_t{1} << 24)) capacity <<= 1;
  std::vector<Accumulator> table(capacity);
  std::vector<std::uint32_t> occupied;
  std::size_t mask = capacity - 1;
  const auto grow = [&] {
    std::vector<Accumulator> bigger(table.size() * 2);
    const std::size_t bigger_mask = bigger.size() - 1;
    for (std::uint32_t& slot : occupied) {
      std::size_t moved = mix(table[slot].key) & bigger_mask;
      while (bigger[moved].count != 0) moved = (moved + 1) & bigger_mask;
      bigger[moved] = table[slot];
      slot = static_cast<std::uint32_t>(moved);
    }
    table.swap(bigger);
    mask = table.size() - 1;
  };
  for (const Point3f& p : cloud.points) {
    const Eigen::Array3f index = ((p.array() - offset) * inverse).floor() - first;
    const std::uint64_t ix = static_cast<std::uint64_t>(index.x());
    const std::uint64_t iy = static_cast<std::uint64_t>(index.y());
    const std::uint64_t iz = static_cast<std::uint64_t>(index.z());
    const std::uint64_t key = ix | (iy << kKeyBits) | (iz << (2 * kKeyBits));
    std::size_t slot = mix(key) & mask;
    while (table[slot].count != 0 && table[slot].key != key) slot = (slot + 1) & mask;
    Accumulator& voxel = table[slot];
    if (voxel.count == 0) {
      voxel.key = key;
      occupied.push_back(static_cast<std::uint32_t>(slot));
    }
    voxel.x += p.x();
    voxel.y += p.y();
    voxel.z += p.z();
    ++voxel.count;
    if (voxel.count == 1 && occupied.size() * 2 > table.size()) grow();
  }
  result.points.reserve(occupied.size());
  for (const std::uint32_t slot : occupied) {
    const Accumulator& voxel = table[slot];
    const float n = static_cast<float>(voxel.count);
    result.points.emplace_back(voxel.x / n, voxel.y / n, voxel.z / n);
  }
  return result;
}

}  // namespace rigdesign
