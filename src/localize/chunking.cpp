#include "rigdesign/localize/chunking.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::localize {
namespace {

constexpr int kChunkKeyBits = 21;  // three signed cell indices packed in 63 bits
constexpr std::int64_t kKeyOffset = std::int64_t{1} << (kChunkKeyBits - 1);
constexpr std::uint64_t kKeyMask = (std::uint64_t{1} << kChunkKeyBits) - 1;

// Cells wrap around beyond +-100 km at 10 cm: far outside any robot's log. The clamp keeps
// the conversion defined for absurd coordinates.
model::Vec3 cell_index(const model::Vec3& position, double size) {
  return (position / size).array().floor().cwiseMax(-1e15).cwiseMin(1e15).matrix();
}

std::uint64_t cell_key(const model::Vec3& index) {
  std::uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const auto cell = static_cast<std::int64_t>(index[axis]) + kKeyOffset;
    key |= (static_cast<std::uint64_t>(cell) & kKeyMask) << (kChunkKeyBits * axis);
  }
  return key;
}

}  // namespace

double wls_weight(const Chunk& chunk) {
  return std::sqrt(static_cast<double>(chunk.count)) / chunk.mean_range();
}

model::Vec3 chunk_centre(const model::Vec3& position, double size) {
  return (cell_index(position, size).array() + 0.5).matrix() * size;
}

std::size_t ChunkAccumulator::add(const model::Vec3& position, double range, double rssi_dbm,
                                  Chunk* previous) {
  const auto [it, inserted] =
      index_of_.try_emplace(cell_key(cell_index(position, params_.size)), chunks_.size());
  if (inserted) {
    chunks_.emplace_back();
    chunks_.back().centre = chunk_centre(position, params_.size);
  }
  Chunk& chunk = chunks_[it->second];
  if (previous != nullptr) *previous = chunk;
  chunk.height_sum += position.z();
  chunk.range_sum += range;
  chunk.rssi_sum += rssi_dbm;
  ++chunk.count;
  return it->second;
}

std::vector<Chunk> chunk_readings(const RssiLog& log, int emitter, const PathLossParams& path_loss,
                                  const ChunkParams& params) {
  ChunkAccumulator accumulator(params);
  for (const RssiReading& reading : log.readings) {
    if (reading.emitter != emitter || !reading.heard || !passes_cutoff(reading.rssi_dbm, path_loss))
      continue;
    accumulator.add(reading.position, range_from_rssi(reading.rssi_dbm, path_loss),
                    reading.rssi_dbm);
  }
  return accumulator.chunks();
}

}  // namespace rigdesign::localize
