#pragma once
#include <string>

#include "rigdesign/model/relaxation_policy.hpp"

namespace rigdesign::io {

/// Reads a relaxation policy: `steps: [{relax: robot_speed.max_speed, to: 0.8}, ...]`, or
/// `{relax: lighting, drop: dark}`. Steps are validated against requirements with relax().
model::RelaxationPolicy load_policy(const std::string& path);

}  // namespace rigdesign::io
