#pragma once
/// Paper 4's chunks: robot positions binned into 10 cm cells (a spatial grid, so a revisited
/// place joins its chunk), each keeping running sums so a new reading updates its chunk in
/// O(1) (one hash look-up). A chunk stands at the centre of its cell, as the thesis bins
/// positions into chunks; its distance and RSSI are the means of its readings'.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "rigdesign/localize/path_loss.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

/// How paper 4's chunk weight w = sqrt(c) / r enters the linearised system B q = a (row j:
/// 2 (p_j - p_1)^T q = k_j - k_1, the first chunk as reference).
enum class WlsWeighting {
  /// Paper 4's eq. 12 read as weighted least squares (issue 33's reading, the default): w
  /// scales both sides of each row, so its squared residual counts w^2 = c / r^2 (a mean of c
  /// readings whose range error grows with r: the inverse of its variance, up to a constant).
  rows,
  /// Before issue 33: w multiplied the squared residual (`--wls-weighting residuals`, kept to
  /// compare with).
  squared_residuals,
  /// Eq. 12 as printed, `diag(w) a = B [x y z]^T` (`--wls-weighting paper`): least squares of
  /// B q = diag(w) a, w scaling only the right-hand side. Not consistent: even noise-free
  /// ranges give a point off the emitter unless every w is 1.
  paper,
};

struct ChunkParams {
  double size = 0.10;  ///< chunk edge [m] (paper 4: 10 cm)
  WlsWeighting weighting = WlsWeighting::rows;
};

struct Chunk {
  model::Vec3 centre = model::Vec3::Zero();  ///< the centre of the chunk's cell [m]
  /// Sum of the readings' antenna heights [m]: kept because a 2D solve reports the emitter at
  /// the antenna's mean height, which the cell centre's z (a multiple of the cell size plus
  /// half) misses by up to half a cell.
  double height_sum = 0.0;
  double range_sum = 0.0;  ///< sum of per-reading distances from RSSI [m]
  double rssi_sum = 0.0;   ///< [dBm]
  int count = 0;           ///< readings in the chunk (paper 4's c)

  /// Where paper 4's methods place the chunk: its cell's centre.
  const model::Vec3& position() const { return centre; }
  double mean_height() const { return height_sum / count; }
  /// Paper 4's averaged distance: the mean of the readings' distances (not the distance of
  /// the mean RSSI).
  double mean_range() const { return range_sum / count; }
  double mean_rssi() const { return rssi_sum / count; }
};

/// Paper 4's chunk weight w = sqrt(c) / r.
double wls_weight(const Chunk& chunk);

/// The centre of the `size` cell holding `position` (the chunk it joins) [m].
model::Vec3 chunk_centre(const model::Vec3& position, double size);

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

/// The chunks of one emitter's heard readings stronger than the cut-off, in order of first visit.
std::vector<Chunk> chunk_readings(const RssiLog& log, int emitter, const PathLossParams& path_loss,
                                  const ChunkParams& params = {});

}  // namespace rigdesign::localize
