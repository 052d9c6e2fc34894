#include "shadowing_correlation.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::localize::detail {
namespace {

constexpr int kShares = 21;          // candidate correlated shares 0, 0.05, ..., 1
constexpr int kLengths = 36;         // candidate L, log-spaced
constexpr double kShortest = 0.05;   // [m]
constexpr double kLongest = 40.0;    // [m]
constexpr std::size_t kMaxSeries = 3000;  // longer residual series are thinned to this

// Log-likelihood of the residuals (mean removed, variance `variance`) under correlated
// shadowing of share `beta` and length `length` plus white fading: a Kalman filter over the
// AR(1) state along the path (exact for this model; gaps of unheard scans just widen a step).
double series_log_likelihood(const std::vector<double>& s, const std::vector<double>& r,
                             double variance, double beta, double length) {
  const double shadowing = beta * variance;
  const double fading = std::max((1.0 - beta) * variance, 1e-9 * variance);
  double mean = 0.0, spread = shadowing, sum = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i > 0) {
      const double rho = std::exp(-(s[i] - s[i - 1]) / length);
      mean *= rho;
      spread = rho * rho * spread + shadowing * (1.0 - rho * rho);
    }
    const double innovation = r[i] - mean;
    const double total = spread + fading;
    sum -= 0.5 * (std::log(total) + innovation * innovation / total);
    const double gain = spread / total;
    mean += gain * innovation;
    spread *= 1.0 - gain;
  }
  return sum;
}

}  // namespace

ResidualCorrelation residual_correlation(const std::vector<double>& travelled,
                                         const std::vector<double>& residuals,
                                         const std::vector<std::size_t>& heard_index) {
  ResidualCorrelation result;
  const std::size_t n = residuals.size();
  if (n < 3) return result;
  double mean = 0.0;
  for (const double r : residuals) mean += r;
  mean /= static_cast<double>(n);
  double variance = 0.0;
  for (const double r : residuals) variance += (r - mean) * (r - mean);
  variance /= static_cast<double>(n);
  if (variance <= 0.0) return result;

  // The residual series along the path, thinned when long (the filter is O(N) per candidate).
  const std::size_t stride = (n + kMaxSeries - 1) / kMaxSeries;
  std::vector<double> at, value;
  for (std::size_t i = 0; i < n; i += stride) {
    at.push_back(travelled[heard_index[i]]);
    value.push_back(residuals[i] - mean);
  }
  // Maximum likelihood over a grid of (share, length): the correlogram of fitted residuals
  // underestimates long lengths, the likelihood much less.
  double best = -INFINITY;
  for (int b = 0; b < kShares; ++b) {
    const double beta = static_cast<double>(b) / (kShares - 1);
    for (int c = 0; c < kLengths; ++c) {
      const double length =
          kShortest * std::pow(kLongest / kShortest, static_cast<double>(c) / (kLengths - 1));
      const double ll = series_log_likelihood(at, value, variance, beta, length);
      if (ll > best) {
        best = ll;
        result.correlated_share = beta;
        result.length = length;
      }
      if (b == 0) break;  // no correlated part: the length does not matter
    }
  }
  if (result.length <= 0.0 || result.correlated_share <= 0.0) return result;
  // sum_{i<j} exp(-(s_j - s_i) / L) over every scan in O(N): each term carries the previous.
  double carried = 0.0, total = 0.0;
  for (std::size_t j = 1; j < travelled.size(); ++j) {
    carried = std::exp(-(travelled[j] - travelled[j - 1]) / result.length) * (carried + 1.0);
    total += carried;
  }
  const double scans = static_cast<double>(travelled.size());
  result.effective_share = scans / (scans + 2.0 * result.correlated_share * total);
  return result;
}

}  // namespace rigdesign::localize::detail
