#pragma once
/// Applying one relaxation step to application requirements.
#include <string>

#include "rigdesign/model/relaxation_policy.hpp"

namespace rigdesign::select {

/// `requirements` with `step` applied. Throws InputError at the step when it names an
/// unknown requirement, one the requirements do not state, a value out of range, or a value
/// that tightens instead of relaxing.
model::Requirements relax(const model::Requirements& requirements,
                          const model::RelaxationStep& step);

/// One line on what a step changes, e.g. "robot_speed.max_speed 1 -> 0.8 m/s".
std::string describe(const model::Requirements& before, const model::RelaxationStep& step);

}  // namespace rigdesign::select
