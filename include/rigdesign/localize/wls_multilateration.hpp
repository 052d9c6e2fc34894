#pragma once
/// Paper 4's estimator: linearised multilateration by weighted least squares over chunks.
/// Each chunk j gives a sphere |q - p_j|^2 = r_j^2; subtracting a reference sphere gives the
/// linear row 2 (p_j - p_ref)^T q = k_j - k_ref with k = |p|^2 - r^2 (p_j the chunk's centre),
/// weighted by w_j = sqrt(c_j) / r_j as WlsWeighting says: on both sides (rows, the default),
/// on the squared residual, or on the right-hand side only (paper: eq. 12 as printed). Paper
/// 4 references the first chunk's sphere; referencing the weighted mean of the spheres is the
/// better-conditioned variant the range fit starts from.
///
/// Every quantity is a sum over chunks of a power of w times 1, p, p p^T, k, p k or k^2, so a
/// new reading updates the system in O(1): its chunk's old contribution is subtracted and the
/// new one added, and solving is a 2x2 or 3x3 system.
#include <array>
#include <optional>

#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

enum class WlsReference { first_chunk, weighted_mean };

struct WlsSolution {
  model::Vec3 position;  ///< [m]; with 2 dimensions z is the chunks' weighted mean height
  /// [m^2] sigma^2 (B^T W B)^-1 from the linear residuals (W: the rows' weights on the
  /// left-hand side, all 1 for WlsWeighting::paper); z row/column 0 in 2D.
  model::Mat3 covariance;
};

/// Sums over chunks of one power of the chunk weight times each term of the normal equations.
struct WlsMoments {
  double s = 0.0, sk = 0.0, skk = 0.0, sz = 0.0;
  model::Vec3 sp = model::Vec3::Zero(), spk = model::Vec3::Zero();
  model::Mat3 spp = model::Mat3::Zero();
  void add(double weight, const model::Vec3& p, double k, double height);
};

/// Running weighted sums of the linear system. Positions are taken relative to `origin` to
/// keep the sums well scaled.
class WlsSums {
 public:
  explicit WlsSums(const model::Vec3& origin = model::Vec3::Zero(),
                   WlsWeighting weighting = WlsWeighting::rows);
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
  /// The power of w weighting the left-hand side (B^T B), the cross term (B^T a) and the
  /// right-hand side (a^T a) of the normal equations.
  int lhs_power_ = 2, cross_power_ = 2, rhs_power_ = 2;
  std::array<WlsMoments, 3> by_power_;  ///< indexed by the power of w (0, 1, 2)
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
