#pragma once
/// A sorted set of disjoint closed intervals on a line: what one sensor covers along a
/// column or the floor of a cross-section.
#include <algorithm>
#include <utility>
#include <vector>

namespace rigdesign::geometry {

/// Pieces of a line shorter than this [m or line parameter] are dropped, and not tested on
/// their own: far below any sensor's resolution, above the rounding of a root.
inline constexpr double kShortestPiece = 1e-12;

/// Splits [t_min, t_max] at `cuts` (sorted here; they must include t_max) and calls
/// `on_piece(low, high)` for each piece longer than kShortestPiece, in increasing order. Every
/// test that is constant between consecutive roots (inside a FOV, a box, a shadow) tests one
/// point per piece this way.
template <typename OnPiece>
void for_each_piece(std::vector<double>& cuts, double t_min, double t_max, OnPiece on_piece) {
  std::sort(cuts.begin(), cuts.end());
  double previous = t_min;
  for (const double cut : cuts) {
    if (cut <= previous) continue;
    const double next = std::min(cut, t_max);
    if (next - previous > kShortestPiece) on_piece(previous, next);
    previous = next;
    if (previous >= t_max) break;
  }
}

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
  /// The parts of this set outside `other` (pieces shorter than kShortestPiece are dropped).
  IntervalSet minus(const IntervalSet& other) const;

 private:
  std::vector<Interval> intervals_;
};

}  // namespace rigdesign::geometry
