#include "rigdesign/localize/chunking.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::localize {
namespace {

constexpr int kChunkKeyBits = 21;  // three signed cell indices packed in 63 bits
constexpr std::int64_t kKeyOffset = std::int64_t{1} << (kChunkKeyBits - 1);
constexpr std::uint64_t kKeyMask = (std::uint64_t{1} << kChunkKeyBits) - 1;

std::uint64_t cell_key(const model::Vec3& position, double size) {
  std::uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    // Cells wrap around beyond +-100 km at 10 cm: far outside any robot's log. The clamp keeps
    // the conversion defined for absurd coordinates.
    const double index = std::clamp(std::floor(position[axis] / size), -1e15, 1e15);
    const auto cell = static_cast<std::int64_t>(index) + kKeyOffset;
    key |= (static_cast<std::uint64_t>(cell) & kKeyMask) << (kChunkKeyBits * axis);
  }
  return key;
}

}  // namespace

double wls_weight(const Chunk& chunk) {
  return std::sqrt(static_cast<double>(chunk.count)) / chunk.mean_range();
}

double squared_residual_weight(const Chunk& chunk, WlsWeighting weighting) {
  const double w = wls_weight(chunk);
  return weighting == WlsWeighting::rows ? w * w : w;
}

std::size_t ChunkAccumulator::add(const model::Vec3& position, double range, double rssi_dbm,
                                  Chunk* previous) {
  const auto [it, inserted] =
      index_of_.try_emplace(cell_key(position, params_.size), chunks_.size());
  if (inserted) chunks_.emplace_back();
  Chunk& chunk = chunks_[it->second];
  if (previous != nullptr) *previous = chunk;
  chunk.position_sum += position;
  chunk.range_sum += range;
  chunk.rssi_sum += rssi_dbm;
  ++chunk.count;
  return it->second;
}

std::vector<Chunk> chunk_readings(const RssiLog& log, int emitter, const PathLossParams& path_loss,
                                  const ChunkParams& params) {
  ChunkAccumulator accumulator(params);
  for (const RssiReading& reading : log.readings) {
    if (reading.emitter != emitter || !reading.heard || reading.rssi_dbm < path_loss.cutoff_dbm)
      continue;
    accumulator.add(reading.position, range_from_rssi(reading.rssi_dbm, path_loss),
                    reading.rssi_dbm);
  }
  return accumulator.chunks();
}

}  // namespace rigdesign::localize
