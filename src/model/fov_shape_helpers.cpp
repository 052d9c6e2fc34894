#include "fov_shape_helpers.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::model {

int angle_steps(double span, double step) {
  return std::max(1, static_cast<int>(std::lround(span / step)));
}

std::string degrees_text(double radians) {
  return format_number(rad_to_deg(radians), 4);
}

}  // namespace rigdesign::model
