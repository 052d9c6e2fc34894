#include "rigdesign/localize/wls_multilateration.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>

namespace rigdesign::localize {
namespace {

// A system whose smallest eigenvalue is below this share of its largest is singular: the
// chunks do not span the dimensions asked for (collinear chunks in 2D, coplanar in 3D).
constexpr double kSingularRatio = 1e-12;

// The powers of w on B^T B, B^T a and a^T a: w on both sides of a row gives w^2 throughout;
// w on the squared residual gives w throughout; eq. 12 as printed (w on a only) gives 1, w
// and w^2.
std::array<int, 3> weight_powers(WlsWeighting weighting) {
  switch (weighting) {
    case WlsWeighting::rows: return {2, 2, 2};
    case WlsWeighting::squared_residuals: return {1, 1, 1};
    case WlsWeighting::paper: return {0, 1, 2};
  }
  return {2, 2, 2};
}

// The normal equations H q = g of the rows 2 (p_j - p_ref)^T q = k_j - k_ref, expanded into
// sums, and the right-hand side's squared norm bb.
struct NormalEquations {
  model::Mat3 H;
  model::Vec3 g;
  double bb;
};

NormalEquations normal_equations(const WlsMoments& lhs, const WlsMoments& cross,
                                 const WlsMoments& rhs, const model::Vec3& p_ref, double k_ref) {
  NormalEquations e;
  e.H = 4.0 * (lhs.spp - lhs.sp * p_ref.transpose() - p_ref * lhs.sp.transpose() +
               lhs.s * p_ref * p_ref.transpose());
  e.g = 2.0 * (cross.spk - k_ref * cross.sp - cross.sk * p_ref + k_ref * cross.s * p_ref);
  e.bb = rhs.skk - 2.0 * k_ref * rhs.sk + k_ref * k_ref * rhs.s;
  return e;
}

}  // namespace

void WlsMoments::add(double weight, const model::Vec3& p, double k, double height) {
  s += weight;
  sk += weight * k;
  skk += weight * k * k;
  sz += weight * height;
  sp += weight * p;
  spk += weight * k * p;
  spp += weight * p * p.transpose();
}

WlsSums::WlsSums(const model::Vec3& origin, WlsWeighting weighting) : origin_(origin) {
  const std::array<int, 3> powers = weight_powers(weighting);
  lhs_power_ = powers[0];
  cross_power_ = powers[1];
  rhs_power_ = powers[2];
}

void WlsSums::add(const Chunk& chunk, double sign) {
  const double w = wls_weight(chunk);
  const model::Vec3 p = chunk.position() - origin_;
  const double r = chunk.mean_range();
  const double k = p.squaredNorm() - r * r;
  const double height = chunk.mean_height() - origin_.z();
  const std::array<double, 3> weights = {1.0, w, w * w};  // by power of w
  for (int power = 0; power < 3; ++power) {
    if (power != lhs_power_ && power != cross_power_ && power != rhs_power_) continue;
    const auto i = static_cast<std::size_t>(power);
    by_power_[i].add(sign * weights[i], p, k, height);
  }
  chunks_ += sign > 0 ? 1 : -1;
}

std::optional<WlsSolution> WlsSums::solve(int dimensions, WlsReference reference,
                                          const Chunk* first_chunk) const {
  const int d = dimensions;
  const WlsMoments& lhs = by_power_[static_cast<std::size_t>(lhs_power_)];
  if (chunks_ < d + 1 || !(lhs.s > 0)) return std::nullopt;
  model::Vec3 p_ref;
  double k_ref = 0.0;
  if (reference == WlsReference::weighted_mean || first_chunk == nullptr) {
    p_ref = lhs.sp / lhs.s;
    k_ref = lhs.sk / lhs.s;
  } else {
    p_ref = first_chunk->position() - origin_;
    const double r = first_chunk->mean_range();
    k_ref = p_ref.squaredNorm() - r * r;
  }
  const NormalEquations e =
      normal_equations(lhs, by_power_[static_cast<std::size_t>(cross_power_)],
                       by_power_[static_cast<std::size_t>(rhs_power_)], p_ref, k_ref);
  const Eigen::MatrixXd H = e.H.topLeftCorner(d, d);
  const Eigen::VectorXd g = e.g.topRows(d);
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
  const double rss = std::max(0.0, q.dot(H * q) - 2.0 * q.dot(g) + e.bb);
  const int rows = chunks_ - (reference == WlsReference::first_chunk ? 1 : 0);
  const double sigma2 = rows > d ? rss / (rows - d) : 0.0;
  WlsSolution solution;
  solution.position = origin_;
  for (int k = 0; k < d; ++k) solution.position(k) += q(k);
  // In 2D the emitter is placed at the antenna's mean height (z is not observable).
  if (d == 2) solution.position.z() = origin_.z() + lhs.sz / lhs.s;
  solution.covariance = model::Mat3::Zero();
  solution.covariance.topLeftCorner(d, d) = sigma2 * H_inverse;
  if (!solution.position.allFinite()) return std::nullopt;
  return solution;
}

bool IncrementalWls::add(const model::Vec3& position, double rssi_dbm) {
  if (!passes_cutoff(rssi_dbm, path_loss_)) return false;
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
