#include "rigdesign/scenarios/sensor_timing.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::scenarios {

MountTiming mount_timing(const model::Mount& mount, const model::SensorMode& mode,
                         double filtering_seconds_per_point, double phase) {
  MountTiming timing;
  const double rate = std::min(mode.frequency, mount.throttle_hz.value_or(mode.frequency));
  timing.period = 1.0 / rate;
  timing.phase = std::fmod(std::max(phase, 0.0), timing.period);
  // The driver's load (a fixed part and a cost per point, paper 1 eq. 5) over one frame of
  // the mode: core-equivalents times the mode's frame period.
  const double points_per_second = mode.points_per_frame * mode.frequency;
  timing.driver = mode.driver_cpu.load(points_per_second) / mode.frequency;
  timing.filtering = filtering_seconds_per_point * mode.points_per_frame;
  return timing;
}

std::vector<long> frames_held(const MountTiming& timing, double t, double persistence, long after) {
  const double newest_capture = t - timing.latency();
  if (newest_capture < timing.phase - 1e-12) return {};
  const long newest =
      static_cast<long>(std::floor((newest_capture - timing.phase) / timing.period + 1e-9));
  std::vector<long> held;
  for (long k = newest; k >= 0 && k > after; --k) {
    if (timing.capture(newest) - timing.capture(k) > persistence + 1e-12) break;
    held.push_back(k);
  }
  std::reverse(held.begin(), held.end());
  return held;
}

std::string describe(const MountTiming& timing) {
  return model::format_number(1.0 / timing.period, 4) + " Hz, latency " +
         model::format_number(timing.latency(), 3) + " s (driver " +
         model::format_number(timing.driver, 3) + " s + filters " +
         model::format_number(timing.filtering, 3) + " s)";
}

}  // namespace rigdesign::scenarios
