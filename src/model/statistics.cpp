#include "rigdesign/model/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rigdesign::model {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The k-th smallest (0-based) of a copy; selection instead of a full sort.
double kth_smallest(std::vector<double>& values, std::size_t k) {
  const auto nth = values.begin() + static_cast<std::ptrdiff_t>(k);
  std::nth_element(values.begin(), nth, values.end());
  return *nth;
}

}  // namespace

double median(std::span<const double> samples) {
  if (samples.empty()) return kNaN;
  std::vector<double> values(samples.begin(), samples.end());
  const std::size_t half = values.size() / 2;
  const double upper = kth_smallest(values, half);
  if (values.size() % 2 == 1) return upper;
  // nth_element leaves the smaller half in front: its largest is the lower middle value.
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(half));
  return 0.5 * (lower + upper);
}

double percentile(std::span<const double> samples, double share) {
  if (samples.empty()) return kNaN;
  std::vector<double> values(samples.begin(), samples.end());
  const double rank = std::ceil(share * static_cast<double>(values.size()));
  const std::size_t index = static_cast<std::size_t>(std::max(1.0, rank)) - 1;
  return kth_smallest(values, std::min(index, values.size() - 1));
}

}  // namespace rigdesign::model
