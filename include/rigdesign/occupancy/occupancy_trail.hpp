#pragma once
/// The trail a mapper leaves behind a moving object (issue 6, beyond paper 3): cells the map
/// still shows occupied after the object has left them. Paper 3's scores only count false
/// positives near the object, so they cannot see it.
#include <cstdint>
#include <span>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::occupancy {

/// One frame of the whole-window picture.
struct TrailFrame {
  double ghost_area = 0.0;  ///< [m^2] cells shown occupied where the truth is free
  double trail_area = 0.0;  ///< [m^2] the ghosts the truth held occupied at some earlier frame
  /// [s] time of the oldest truth occupation among the trail's cells (when the object left the
  /// trail's far end); NaN without a trail.
  double oldest_trail_time = 0.0;
  /// [s] the time after which the object left 90 % of the trail's cells (nearest rank), so a
  /// few stale cells that no ray crosses again do not set the trail's length; NaN without one.
  double trail_p90_time = 0.0;
};

/// Tracks, per cell of a fixed 2D window, when the truth last held it occupied. A ghost whose
/// cell the truth held before is trail; one the truth never held (noise, a stray return) is
/// only a ghost.
class TrailTracker {
 public:
  /// `cells` cells of `cell_area` [m^2] each.
  TrailTracker(std::size_t cells, double cell_area);
  /// One frame at `time` [s] (non-decreasing); masks as in compare_masks (non-zero = occupied).
  /// Throws std::invalid_argument when a mask's size differs from `cells`.
  TrailFrame record(double time, std::span<const std::uint8_t> truth,
                    std::span<const std::uint8_t> predicted);

 private:
  std::vector<double> last_occupied_;  // NaN: never
  double cell_area_;
  std::vector<double> trail_times_;  // scratch
};

/// The arc length of a path recorded frame by frame, to turn a trail's age into metres.
class PathOdometer {
 public:
  /// Appends the position [m] at `time` [s] (increasing).
  void record(double time, const model::Vec2& position);
  /// [m] path length from the last recorded frame at or before `since` to the newest one
  /// (from the first when `since` is earlier; 0 when nothing is recorded).
  double length_since(double since) const;

 private:
  std::vector<double> times_;
  std::vector<double> cumulative_;  // [m] length from the first position to each
  model::Vec2 last_ = model::Vec2::Zero();
};

}  // namespace rigdesign::occupancy
