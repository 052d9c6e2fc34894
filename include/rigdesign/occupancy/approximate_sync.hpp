#pragma once
/// Paper 3's fusion of its four sensors' clouds with ROS's approximate-time filter
/// (message_filters::sync_policies::ApproximateTime, ros/ros_comm 845f746,
/// utilities/message_filters/include/message_filters/sync_policies/approximate_time.h: one
/// message per topic, the set with the smallest spread between its stamps, L790-815; the
/// default maximum interval is unlimited, L118). Each sensor publishes at its own rate and
/// phase; at an evaluation tick the fused set is the one a subscriber would hold by then.
#include <cstdint>
#include <span>
#include <vector>

namespace rigdesign::occupancy {

/// A sensor's frame clock: stamps phase + n x period.
struct FrameClock {
  double period = 0.1;  ///< [s]
  double phase = 0.0;   ///< [s] in [0, period)
};

/// The latest stamp of `clock` at or before `t` [s].
double latest_stamp(const FrameClock& clock, double t);

/// One stamp per clock: among the sets whose latest stamp is at or before `tick`, the one with
/// the smallest spread (each sensor's latest frame at or before the set's latest stamp); of
/// equal spreads, the later set. Throws std::invalid_argument for no clocks or a period <= 0.
std::vector<double> approximate_time_set(std::span<const FrameClock> clocks, double tick);

/// Each sensor's clock at its frequency [Hz], its phase drawn uniformly in [0, period) from a
/// stream of (seed, sensors + index), independent of the sensors' noise streams.
std::vector<FrameClock> frame_clocks(std::span<const double> frequencies, std::uint64_t seed);

}  // namespace rigdesign::occupancy
