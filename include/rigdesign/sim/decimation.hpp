#pragma once
/// Sparser ray patterns for runs that simulate many frames (robot in the loop, the occupancy
/// cell): speed at the cost of resolution, the same rule for every caller.
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::sim {

/// `mode` with every `camera_stride`-th pixel row and column of a camera (pyramid or cone),
/// or every `lidar_stride`-th ray along the scan of any other sensor; points per frame shrink
/// to match. Lidar rings are never dropped: the lowest beam decides what a lidar sees low
/// down. Strides below 1 count as 1 (the mode unchanged).
model::SensorMode decimated_mode(model::SensorMode mode, int camera_stride, int lidar_stride);

}  // namespace rigdesign::sim
