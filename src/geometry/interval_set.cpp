#include "rigdesign/geometry/interval_set.hpp"

#include <algorithm>

namespace rigdesign::geometry {

void IntervalSet::append(double low, double high) {
  if (high < low) return;
  if (!intervals_.empty() && low <= intervals_.back().second) {
    intervals_.back().second = std::max(intervals_.back().second, high);
    return;
  }
  intervals_.emplace_back(low, high);
}

double IntervalSet::length() const {
  double total = 0.0;
  for (const auto& [low, high] : intervals_) total += high - low;
  return total;
}

bool IntervalSet::contains(double x) const {
  return std::any_of(intervals_.begin(), intervals_.end(),
                     [x](const Interval& i) { return i.first <= x && x <= i.second; });
}

IntervalSet IntervalSet::united(const IntervalSet& other) const {
  std::vector<Interval> all = intervals_;
  all.insert(all.end(), other.intervals_.begin(), other.intervals_.end());
  std::sort(all.begin(), all.end());
  IntervalSet result;
  for (const auto& [low, high] : all) result.append(low, high);
  return result;
}

IntervalSet IntervalSet::minus(const IntervalSet& other) const {
  IntervalSet result;
  std::size_t k = 0;
  for (const auto& [low, high] : intervals_) {
    double from = low;
    while (k < other.intervals_.size() && other.intervals_[k].second <= from) ++k;
    for (std::size_t j = k; j < other.intervals_.size() && other.intervals_[j].first < high; ++j) {
      if (other.intervals_[j].first - from > kShortestPiece)
        result.append(from, other.intervals_[j].first);
      from = std::max(from, other.intervals_[j].second);
    }
    if (high - from > kShortestPiece) result.append(from, high);
  }
  return result;
}

}  // namespace rigdesign::geometry
