#include "rigdesign/model/requirements.hpp"

#include <algorithm>

namespace rigdesign::model {

double Requirements::required_frequency() const {
  double frequency = min_frequency.value_or(0.0);
  if (object_dynamics) frequency = std::max(frequency, object_dynamics->min_frequency());
  if (robot_speed) frequency = std::max(frequency, robot_speed->min_frequency());
  return frequency;
}

}  // namespace rigdesign::model
