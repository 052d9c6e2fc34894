// Paired bootstrap over the seeds of paper 2's Table 1 (issue 54).
#include "rigdesign/scenarios/seed_bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace rigdesign::scenarios {

std::vector<std::vector<std::size_t>> seed_resamples(std::size_t count, int rounds,
                                                     std::uint64_t seed) {
  std::vector<std::vector<std::size_t>> resamples;
  if (count == 0 || rounds <= 0) return resamples;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, count - 1);
  resamples.resize(static_cast<std::size_t>(rounds));
  for (std::vector<std::size_t>& resample : resamples) {
    resample.resize(count);
    for (std::size_t& index : resample) index = pick(rng);
  }
  return resamples;
}

double resampled_critical_distance(const VariantOutcome& outcome,
                                   const std::vector<double>& margins,
                                   const std::vector<std::size_t>& picked) {
  const std::size_t tried = std::min(margins.size(), outcome.collided_by_margin.size());
  for (std::size_t m = 0; m < tried; ++m) {
    const std::vector<bool>& collided = outcome.collided_by_margin[m];
    const bool clear =
        std::none_of(picked.begin(), picked.end(), [&](std::size_t i) { return collided.at(i); });
    if (clear) return margins[m];
  }
  return std::numeric_limits<double>::infinity();
}

double resampled_average_speed(const VariantOutcome& outcome,
                               const std::vector<std::size_t>& picked) {
  std::vector<RunSummary> runs;
  runs.reserve(picked.size());
  for (const std::size_t i : picked) runs.push_back(outcome.runs.at(i));
  return means_of(runs).average_speed;
}

Interval percentile_interval(std::vector<double> values, double level) {
  if (values.empty()) throw std::invalid_argument("percentile_interval: no values");
  if (!(level > 0.0 && level < 1.0))
    throw std::invalid_argument("percentile_interval: level outside (0, 1)");
  std::sort(values.begin(), values.end());
  const double n = static_cast<double>(values.size());
  // 40 x (1 - 0.95) / 2 is 1.0000000000000009 in double: a rank that is whole up to rounding
  // stays that rank.
  const auto at_rank = [&](double rank) {
    const double clamped = std::clamp(std::ceil(rank - 1e-9), 1.0, n);
    return values[static_cast<std::size_t>(clamped) - 1];
  };
  return {at_rank(n * (1.0 - level) / 2.0), at_rank(n * (1.0 + level) / 2.0)};
}

}  // namespace rigdesign::scenarios
