#pragma once
/// Paper 4's estimator: linearised multilateration by weighted least squares over chunks.
/// Each chunk j gives a sphere |q - p_j|^2 = r_j^2; subtracting a reference sphere gives the
/// linear row 2 (p_j - p_ref)^T q = k_j - k_ref with k = |p|^2 - r^2, weighted by
/// w_j = sqrt(c_j) / r_j (minimising sum w_j e_j^2). Paper 4 references the first chunk's
/// sphere; referencing the weighted mean of the spheres is the better-conditioned variant
/// the range fit starts from.
///
/// Every quantity is a sum over chunks (sum w, w p, w p p^T, w k, w p k, w k^2), so a new
/// reading updates the system in O(1): its chunk's old contribution is subtracted and the
/// new one added, and solving is a 2x2 or 3x3 system.
#include <optional>

#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

enum class WlsReference { first_chunk, weighted_mean };

struct WlsSolution {
  model::Vec3 position;  ///< [m]; with 2 dimensions z is the chunks' weighted mean height
  model::Mat3
      covariance;  ///< [m^2] sigma^2 (A^T W A)^-1 from the linear residuals; z row/column 0 in 2D
};

/// Running weighted sums of the linear system. Positions are taken relative to `origin` to
/// keep the sums well scaled.
class WlsSums {
 public:
  explicit WlsSums(const model::Vec3& origin = model::Vec3::Zero(),
                   WlsWeighting weighting = WlsWeighting::rows)
      : origin_(origin), weighting_(weighting) {}
  /// Adds (sign +1) or removes (sign -1) a chunk's contribution.
  void add(const Chunk& chunk, double sign = 1.0);
  /// Solves in the first `dimensions` (2: x, y; 3: x, y, z) coordinates; the reference chunk
  /// for WlsReference::first_chunk is passed in. Empty when fewer than dimensions + 1
  /// chunks or the system is singular (e.g. collinear chunks).
  std::optional<WlsSolution> solve(int dimensions, WlsReference reference,
                                   const Chunk* first_chunk) const;
  int chunks() const { return chunks_; }

 private:
  model::Vec3 origin_;
  WlsWeighting weighting_;
  double w_ = 0.0, wk_ = 0.0, wkk_ = 0.0, wz_ = 0.0;
  model::Vec3 wp_ = model::Vec3::Zero(), wpk_ = model::Vec3::Zero();
  model::Mat3 wpp_ = model::Mat3::Zero();
  int chunks_ = 0;
};

/// Paper 4's online estimator: chunks and the weighted sums updated per reading in O(1).
class IncrementalWls {
 public:
  explicit IncrementalWls(PathLossParams path_loss = {}, ChunkParams chunking = {})
      : path_loss_(path_loss), weighting_(chunking.weighting), accumulator_(chunking) {}
  /// Adds one reading; false (and nothing changes) when it is below the cut-off.
  bool add(const model::Vec3& position, double rssi_dbm);
  std::optional<WlsSolution> solve(int dimensions,
                                   WlsReference reference = WlsReference::first_chunk) const;
  const std::vector<Chunk>& chunks() const { return accumulator_.chunks(); }

 private:
  PathLossParams path_loss_;
  WlsWeighting weighting_;
  ChunkAccumulator accumulator_;
  std::optional<WlsSums> sums_;
};

/// Batch form over a list of chunks (the same system as IncrementalWls builds).
std::optional<WlsSolution> wls_multilateration(const std::vector<Chunk>& chunks, int dimensions,
                                               WlsReference reference = WlsReference::first_chunk,
                                               WlsWeighting weighting = WlsWeighting::rows);

}  // namespace rigdesign::localize
