#pragma once
/// When a simulated sensor's frames exist and when the costmap can use them (issue 35 item 1).
/// Each mount captures a frame every period (1 / its mode's frequency, or its throttle_hz when
/// lower), starting at a phase drawn per mount (sensors are not synchronised), and a frame
/// reaches the costmap `latency` after its capture: the driver's time per frame (sensors.yaml
/// driver_cpu at the mode's rate) plus the filters' (seconds per point times the frame's
/// points), both on the reference machine sensors.yaml names. Transport and the costmap's own
/// time are not counted.
#include <string>
#include <vector>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::scenarios {

/// Paper 1's filtering cost per delivered point [core-s] (its best pipeline under 0.05 s on a
/// 144,545-point Azure Kinect cloud: DESIGN.md section 6), used where nothing was measured.
inline constexpr double kPaperFilteringSecondsPerPoint = 3.5e-7;

struct MountTiming {
  double period = 0.0;     ///< [s] between captures
  double phase = 0.0;      ///< [s] the first capture, in [0, period)
  double driver = 0.0;     ///< [s] the driver's time per frame
  double filtering = 0.0;  ///< [s] the filters' time per frame
  double latency() const { return driver + filtering; }
  /// Capture time of frame `k` [s].
  double capture(long k) const { return phase + static_cast<double>(k) * period; }
};

/// The timing of `mount` in `mode` with `filtering_seconds_per_point` [core-s] and a first
/// capture at `phase` [s] (taken modulo the period).
MountTiming mount_timing(const model::Mount& mount, const model::SensorMode& mode,
                         double filtering_seconds_per_point, double phase);

/// Indices k of the frames the costmap holds at time `t` [s]: those available by then
/// (capture(k) + latency <= t) captured no earlier than `persistence` [s] before the newest
/// available one, as nav2's observation buffer keeps them (persistence 0: the newest only).
/// Empty before the first frame arrives. Only frames after index `after` are listed: a caller
/// that has passed the older ones on does not walk them again (with a long persistence, every
/// frame since the start at every update).
std::vector<long> frames_held(const MountTiming& timing, double t, double persistence,
                              long after = -1);

/// One line per timing for reports: "10 Hz, latency 0.012 s (driver 0.004 s + filters 0.008 s)".
std::string describe(const MountTiming& timing);

}  // namespace rigdesign::scenarios
