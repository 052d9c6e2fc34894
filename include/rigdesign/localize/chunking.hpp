#pragma once
/// Paper 4's chunks: robot positions binned into 10 cm cells (a spatial grid, so a revisited
/// place joins its chunk), each keeping running sums so a new reading updates its chunk in
/// O(1) (one hash look-up) and the chunk's mean position, distance and RSSI are read off.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "rigdesign/localize/path_loss.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

/// How paper 4's chunk weight w = sqrt(c) / r enters the least-squares system.
enum class WlsWeighting {
  /// Paper 4's eq. 12 as issue 33's audit of the thesis reads it: w scales each chunk's
  /// linearised equation, so its squared residual counts w^2 = c / r^2 (a mean of c readings
  /// whose range error grows with r: the inverse of its variance, up to a constant).
  rows,
  /// Before issue 33: w multiplied the squared residual (`--wls-weighting residuals`, kept to
  /// compare with).
  squared_residuals,
};

struct ChunkParams {
  double size = 0.10;  ///< chunk edge [m] (paper 4: 10 cm)
  WlsWeighting weighting = WlsWeighting::rows;
};

struct Chunk {
  model::Vec3 position_sum = model::Vec3::Zero();  ///< [m]
  double range_sum = 0.0;                          ///< sum of per-reading distances from RSSI [m]
  double rssi_sum = 0.0;                           ///< [dBm]
  int count = 0;                                   ///< readings in the chunk (paper 4's c)

  model::Vec3 position() const { return position_sum / count; }
  /// Paper 4's averaged distance: the mean of the readings' distances (not the distance of
  /// the mean RSSI).
  double mean_range() const { return range_sum / count; }
  double mean_rssi() const { return rssi_sum / count; }
};

/// Paper 4's chunk weight w = sqrt(c) / r.
double wls_weight(const Chunk& chunk);

/// The weight of the chunk's squared residual in the least-squares sum: w^2 (rows) or w.
double squared_residual_weight(const Chunk& chunk, WlsWeighting weighting);

class ChunkAccumulator {
 public:
  explicit ChunkAccumulator(ChunkParams params = {}) : params_(params) {}
  /// Adds one reading with its distance from RSSI; returns the index of its chunk in
  /// chunks(). O(1) amortised. When `previous` is given it receives the chunk as it was
  /// before the reading (count 0 for a new chunk), so running sums can swap it out exactly.
  std::size_t add(const model::Vec3& position, double range, double rssi_dbm,
                  Chunk* previous = nullptr);
  const std::vector<Chunk>& chunks() const { return chunks_; }

 private:
  ChunkParams params_;
  std::vector<Chunk> chunks_;
  std::unordered_map<std::uint64_t, std::size_t> index_of_;
};

/// The chunks of one emitter's heard readings at or above the cut-off, in order of first visit.
std::vector<Chunk> chunk_readings(const RssiLog& log, int emitter, const PathLossParams& path_loss,
                                  const ChunkParams& params = {});

}  // namespace rigdesign::localize
