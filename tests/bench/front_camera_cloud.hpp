#pragma once
// Real camera clouds placed on a robot for the filter benchmarks.
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::bench {

/// A cloud from a camera's optical frame, placed as the UR Cleaner's front camera (0.46 m
/// ahead, 0.75 m up, pitched 25 deg down) so the floor stages have a robot frame.
model::PointCloud as_front_camera(const model::PointCloud& optical);

}  // namespace rigdesign::bench
