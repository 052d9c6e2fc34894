#pragma once
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// Signed area of a simple polygon by the shoelace formula [m^2]: positive when its
/// vertices run counter-clockwise.
double signed_area(const std::vector<Vec2>& polygon);

}  // namespace rigdesign::model
