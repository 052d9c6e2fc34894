#pragma once
/// A sorted set of disjoint closed intervals on a line: what one sensor covers along a
/// column or the floor of a cross-section.
#include <utility>
#include <vector>

namespace rigdesign::geometry {

class IntervalSet {
 public:
  using Interval = std::pair<double, double>;

  IntervalSet() = default;
  /// Adds [low, high]; intervals must be added in increasing order. Touching or overlapping
  /// ones merge.
  void append(double low, double high);
  const std::vector<Interval>& intervals() const { return intervals_; }
  bool empty() const { return intervals_.empty(); }
  double length() const;
  bool contains(double x) const;

  IntervalSet united(const IntervalSet& other) const;
  /// The parts of this set outside `other` (pieces shorter than 1e-12 are dropped).
  IntervalSet minus(const IntervalSet& other) const;

 private:
  std::vector<Interval> intervals_;
};

}  // namespace rigdesign::geometry
