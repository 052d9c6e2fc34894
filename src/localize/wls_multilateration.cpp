#include "rigdesign/localize/wls_multilateration.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace rigdesign::localize {
namespace {

// A system whose smallest eigenvalue is below this share of its largest is singular: the
// chunks do not span the dimensions asked for (collinear chunks in 2D, coplanar in 3D).
constexpr double kSingularRatio = 1e-12;

}  // namespace

void WlsSums::add(const Chunk& chunk, double sign) {
  const double w = sign * squared_residual_weight(chunk, weighting_);
  const model::Vec3 p = chunk.position() - origin_;
  const double r = chunk.mean_range();
  const double k = p.squaredNorm() - r * r;
  w_ += w;
  wk_ += w * k;
  wkk_ += w * k * k;
  wz_ += w * p.z();
  wp_ += w * p;
  wpk_ += w * k * p;
  wpp_ += w * p * p.transpose();
  chunks_ += sign > 0 ? 1 : -1;
}

std::optional<WlsSolution> WlsSums::solve(int dimensions, WlsReference reference,
                                          const Chunk* first_chunk) const {
  const int d = dimensions;
  if (chunks_ < d + 1 || !(w_ > 0)) return std::nullopt;
  model::Vec3 p_ref;
  double k_ref = 0.0;
  if (reference == WlsReference::weighted_mean || first_chunk == nullptr) {
    p_ref = wp_ / w_;
    k_ref = wk_ / w_;
  } else {
    p_ref = first_chunk->position() - origin_;
    const double r = first_chunk->mean_range();
    k_ref = p_ref.squaredNorm() - r * r;
  }
  // Normal equations of the rows 2 (p_j - p_ref)^T q = k_j - k_ref, expanded into the sums.
  const model::Mat3 H3 = 4.0 * (wpp_ - wp_ * p_ref.transpose() - p_ref * wp_.transpose() +
                                w_ * p_ref * p_ref.transpose());
  const model::Vec3 g3 = 2.0 * (wpk_ - k_ref * wp_ - wk_ * p_ref + k_ref * w_ * p_ref);
  const double bb = wkk_ - 2.0 * k_ref * wk_ + k_ref * k_ref * w_;
  const Eigen::MatrixXd H = H3.topLeftCorner(d, d);
  const Eigen::VectorXd g = g3.topRows(d);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(H);
  const double largest = eigen.eigenvalues().maxCoeff();
  if (!(largest > 0) || eigen.eigenvalues().minCoeff() < kSingularRatio * largest)
    return std::nullopt;
  const Eigen::MatrixXd H_inverse = eigen.eigenvectors() *
                                    eigen.eigenvalues().cwiseInverse().asDiagonal() *
                                    eigen.eigenvectors().transpose();
  const Eigen::VectorXd q = H_inverse * g;
  // Residual sum of squares of the weighted rows, for sigma^2 (rows: one per chunk, minus the
  // reference's zero row when referenced to the first chunk).
  const double rss = std::max(0.0, q.dot(H * q) - 2.0 * q.dot(g) + bb);
  const int rows = chunks_ - (reference == WlsReference::first_chunk ? 1 : 0);
  const double sigma2 = rows > d ? rss / (rows - d) : 0.0;
  WlsSolution solution;
  solution.position = origin_;
  for (int k = 0; k < d; ++k) solution.position(k) += q(k);
  if (d == 2) solution.position.z() = origin_.z() + wz_ / w_;
  solution.covariance = model::Mat3::Zero();
  solution.covariance.topLeftCorner(d, d) = sigma2 * H_inverse;
  if (!solution.position.allFinite()) return std::nullopt;
  return solution;
}

bool IncrementalWls::add(const model::Vec3& position, double rssi_dbm) {
  if (rssi_dbm < path_loss_.cutoff_dbm) return false;
  if (!sums_) sums_.emplace(position, weighting_);
  // The chunk's old contribution out, the reading in, the new contribution back: O(1).
  Chunk previous;
  const std::size_t index =
      accumulator_.add(position, range_from_rssi(rssi_dbm, path_loss_), rssi_dbm, &previous);
  if (previous.count > 0) sums_->add(previous, -1.0);
  sums_->add(accumulator_.chunks()[index], 1.0);
  return true;
}

std::optional<WlsSolution> IncrementalWls::solve(int dimensions, WlsReference reference) const {
  if (!sums_) return std::nullopt;
  return sums_->solve(dimensions, reference, &accumulator_.chunks().front());
}

std::optional<WlsSolution> wls_multilateration(const std::vector<Chunk>& chunks, int dimensions,
                                               WlsReference reference, WlsWeighting weighting) {
  if (chunks.empty()) return std::nullopt;
  WlsSums sums(chunks.front().position(), weighting);
  for (const Chunk& chunk : chunks) sums.add(chunk);
  return sums.solve(dimensions, reference, &chunks.front());
}

}  // namespace rigdesign::localize
