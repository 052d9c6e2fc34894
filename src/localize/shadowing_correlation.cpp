#include "shadowing_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace rigdesign::localize::detail {
namespace {

constexpr int kShares = 11;              // candidate correlated shares 0, 0.1, ..., 1
constexpr int kLengths = 24;             // candidate L, log-spaced
constexpr double kShortest = 0.05;       // [m]
constexpr double kLongest = 40.0;        // [m]
constexpr std::size_t kMaxSeries = 400;  // longer residual series are thinned to this
constexpr double kRejected = 5.99 / 2;   // log-likelihood below the best that rejects a pair

// Log-likelihood of the residuals (mean removed, variance `variance`) under correlated
// shadowing of share `beta` plus white fading, the step correlations `rho` (exp(-ds / L)) given:
// a Kalman filter over the AR(1) state along the path (exact for this model; gaps of unheard
// scans just widen a step).
double series_log_likelihood(const std::vector<double>& rho, const std::vector<double>& r,
                             double variance, double beta) {
  const double shadowing = beta * variance;
  const double fading = std::max((1.0 - beta) * variance, 1e-9 * variance);
  // The log of the innovation variances' product, taken every kLogEvery steps: a log per step
  // was most of this function's time. Each variance divided by the residuals' lies in [1e-9, 1],
  // so eight such ratios multiplied stay far inside a double's range.
  constexpr std::size_t kLogEvery = 8;
  double mean = 0.0, spread = shadowing, squares = 0.0, product = 1.0, log_product = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i > 0) {
      mean *= rho[i];
      spread = rho[i] * rho[i] * spread + shadowing * (1.0 - rho[i] * rho[i]);
    }
    const double innovation = r[i] - mean;
    const double total = spread + fading;
    squares += innovation * innovation / total;
    product *= total / variance;
    if ((i + 1) % kLogEvery == 0) {
      log_product += std::log(product);
      product = 1.0;
    }
    const double gain = spread / total;
    mean += gain * innovation;
    spread *= 1.0 - gain;
  }
  log_product += std::log(product) + static_cast<double>(r.size()) * std::log(variance);
  return -0.5 * (log_product + squares);
}

// sum_{i<j} exp(-(s_j - s_i) / L) in O(N): each term carries the previous one. The effective
// share is then k = N / (N + 2 beta sum).
double correlation_sum(const std::vector<double>& travelled, double length) {
  double carried = 0.0, total = 0.0;
  for (std::size_t j = 1; j < travelled.size(); ++j) {
    carried = std::exp(-(travelled[j] - travelled[j - 1]) / length) * (carried + 1.0);
    total += carried;
  }
  return total;
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
  // The likelihood over a grid of (share, length): the correlogram of fitted residuals
  // underestimates long lengths, the likelihood much less. The fit has soaked up part of the
  // shadowing and a short series says little about long lengths, so the tempering uses the
  // most correlated pair the residuals do not reject (likelihood ratio at 95 %, two degrees of
  // freedom: within 5.99 / 2 of the best), not the best fit alone.
  struct Candidate {
    double beta, length, ll;
  };
  std::vector<Candidate> candidates;
  double best = -INFINITY;
  std::vector<double> rho(at.size(), 0.0);
  for (int c = 0; c < kLengths; ++c) {
    const double length =
        kShortest * std::pow(kLongest / kShortest, static_cast<double>(c) / (kLengths - 1));
    for (std::size_t i = 1; i < at.size(); ++i) rho[i] = std::exp(-(at[i] - at[i - 1]) / length);
    // Share 0 (no correlated part) does not depend on the length: once, with the first.
    for (int b = c == 0 ? 0 : 1; b < kShares; ++b) {
      const double beta = static_cast<double>(b) / (kShares - 1);
      const double ll = series_log_likelihood(rho, value, variance, beta);
      candidates.push_back({beta, length, ll});
      if (ll > best) {
        best = ll;
        result.correlated_share = beta;
        result.length = length;
      }
    }
  }
  // k for every accepted pair is N / (N + 2 beta S(L)), and S grows with L: for each share only
  // its longest accepted length can give the smallest k (S over the whole series is the costly
  // part: one exponential per scan).
  std::vector<double> longest(kShares, 0.0);
  for (const Candidate& candidate : candidates) {
    if (candidate.ll < best - kRejected || candidate.beta <= 0.0) continue;
    const auto b = static_cast<std::size_t>(std::lround(candidate.beta * (kShares - 1)));
    longest[b] = std::max(longest[b], candidate.length);
  }
  result.effective_share = 1.0;
  std::map<double, double> pair_sums;  // S by length: shares often share their longest length
  const double scans = static_cast<double>(travelled.size());
  for (int b = kShares - 1; b > 0; --b) {
    const double length = longest[static_cast<std::size_t>(b)];
    if (length <= 0.0) continue;
    auto known = pair_sums.find(length);
    if (known == pair_sums.end())
      known = pair_sums.emplace(length, correlation_sum(travelled, length)).first;
    const double pair_sum = known->second;
    const double beta = static_cast<double>(b) / (kShares - 1);
    result.effective_share =
        std::min(result.effective_share, scans / (scans + 2.0 * beta * pair_sum));
  }
  return result;
}

}  // namespace rigdesign::localize::detail
