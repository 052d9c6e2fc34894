#pragma once
/// The one definition of the summary statistics every report prints (filter and costmap
/// times, occupancy delays, localisation errors, gas baselines), so "median" means the same
/// thing everywhere.
#include <span>

namespace rigdesign::model {

/// The median: the middle value of the sorted samples, or the mean of the two middle values
/// when their count is even. NaN for no samples. O(n); the input is not changed.
double median(std::span<const double> samples);

/// The nearest-rank percentile: the smallest sample with at least `share` of the samples at
/// or below it, i.e. the ceil(share * n)-th smallest (the smallest for share <= 1/n). `share`
/// in (0, 1]; NaN for no samples. O(n); the input is not changed.
double percentile(std::span<const double> samples, double share);

}  // namespace rigdesign::model
