// Issue 54 item 2: the four sensors' frames fused as ROS's approximate-time filter pairs them.
#include "rigdesign/occupancy/approximate_sync.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "rigdesign/sim/noise_stream.hpp"

namespace rigdesign::occupancy {

double latest_stamp(const FrameClock& clock, double t) {
  return clock.phase + std::floor((t - clock.phase) / clock.period + 1e-9) * clock.period;
}

std::vector<double> approximate_time_set(std::span<const FrameClock> clocks, double tick) {
  if (clocks.empty()) throw std::invalid_argument("approximate_time_set: no sensor clocks");
  for (const FrameClock& clock : clocks) {
    if (!(clock.period > 0.0)) throw std::invalid_argument("approximate_time_set: period <= 0");
  }
  // The best set ends at some sensor's latest frame: try each as the set's latest stamp.
  std::vector<double> best;
  double best_spread = 0.0, best_end = 0.0;
  for (const FrameClock& pivot : clocks) {
    const double end = latest_stamp(pivot, tick);
    std::vector<double> set;
    for (const FrameClock& clock : clocks) set.push_back(latest_stamp(clock, end));
    const double spread = end - *std::min_element(set.begin(), set.end());
    const bool better = best.empty() || spread < best_spread - 1e-12 ||
                        (spread <= best_spread + 1e-12 && end > best_end);
    if (better) best = std::move(set), best_spread = spread, best_end = end;
  }
  return best;
}

std::vector<FrameClock> frame_clocks(std::span<const double> frequencies, std::uint64_t seed) {
  std::vector<FrameClock> clocks;
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    if (!(frequencies[i] > 0.0))
      throw std::invalid_argument("frame_clocks: a sensor's frequency must be positive");
    const double period = 1.0 / frequencies[i];
    std::mt19937_64 stream = sim::noise_stream(seed, frequencies.size() + i);
    clocks.push_back({period, std::uniform_real_distribution<double>(0.0, period)(stream)});
  }
  return clocks;
}

}  // namespace rigdesign::occupancy
