#pragma once
/// What a window-matching depth camera (structured light, stereo) reports along one pixel's
/// ray (issue 54 item 1). The camera finds a pixel's disparity by matching the window of pixels
/// around it, so the pixel gets the depth of the surface that fills most of its window: a
/// surface filling less than about half of it (a thin table leg at range) takes the depth of
/// what lies behind it, and a window split among several depths, none filling most of it,
/// gives no depth. The window is sampled as a 3 x 3 grid of rays at a third of its side apart
/// (each ray the centre of one ninth of the window); two depths are one surface while their
/// disparities differ by under a pixel.
#include <functional>
#include <optional>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/sim/ray_caster.hpp"

namespace rigdesign::sim {

/// The range [m] the camera reports along the unit `direction` (world frame) from `origin`,
/// whose own first hit lies at `centre` [m]; nothing when no surface fills most of the window.
/// `up` is the sensor's z axis in the world frame (the window's columns run along it). A
/// window ray hitting beyond `free_range` [m] ends on the robot there (robot_occlusion.hpp).
std::optional<double> matched_range(const RayCaster& scene, const model::Vec3& origin,
                                    const model::Vec3& direction, const model::Vec3& up,
                                    double centre, const model::DepthMatching& matching,
                                    double free_range);

/// The rule itself: the centre's range [m] if at least 5 of the window's 9 rays agree with it,
/// else the first of the other rays' ranges that 5 agree with, else nothing. `sample(row,
/// column)`, row and column in {-1, 0, 1} and not both 0, gives the range of the window's ray a
/// third of its side up and to the left times row and column (infinity: no return).
std::optional<double> window_majority(double centre, const std::function<double(int, int)>& sample,
                                      double baseline_focal);

}  // namespace rigdesign::sim
