#include "rigdesign/occupancy/occupancy_trail.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rigdesign/model/statistics.hpp"

namespace rigdesign::occupancy {
namespace {

constexpr double kNever = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TrailTracker::TrailTracker(std::size_t cells, double cell_area)
    : last_occupied_(cells, kNever), cell_area_(cell_area) {}

TrailFrame TrailTracker::record(double time, std::span<const std::uint8_t> truth,
                                std::span<const std::uint8_t> predicted) {
  if (truth.size() != last_occupied_.size() || predicted.size() != last_occupied_.size()) {
    throw std::invalid_argument("TrailTracker::record: the masks differ in size");
  }
  std::size_t ghosts = 0;
  std::vector<double>& times = trail_times_;
  times.clear();
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i] != 0) {
      last_occupied_[i] = time;
      continue;
    }
    if (predicted[i] == 0) continue;
    ++ghosts;
    if (std::isnan(last_occupied_[i])) continue;
    times.push_back(last_occupied_[i]);
  }
  TrailFrame frame{static_cast<double>(ghosts) * cell_area_,
                   static_cast<double>(times.size()) * cell_area_, kNever, kNever};
  if (!times.empty()) {
    frame.oldest_trail_time = *std::min_element(times.begin(), times.end());
    // The 90 % youngest cells: the 10th percentile of the leaving times.
    frame.trail_p90_time = model::percentile(times, 0.1);
  }
  return frame;
}

void PathOdometer::record(double time, const model::Vec2& position) {
  const double previous =
      cumulative_.empty() ? 0.0 : cumulative_.back() + (position - last_).norm();
  times_.push_back(time);
  cumulative_.push_back(previous);
  last_ = position;
}

double PathOdometer::length_since(double since) const {
  if (times_.empty()) return 0.0;
  // The last frame at or before `since`; the first when none is.
  const auto after = std::upper_bound(times_.begin(), times_.end(), since);
  const std::size_t from =
      after == times_.begin() ? 0 : static_cast<std::size_t>(after - times_.begin()) - 1;
  return cumulative_.back() - cumulative_[from];
}

}  // namespace rigdesign::occupancy
