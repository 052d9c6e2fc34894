#pragma once
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::io {

/// Resolves every mount's sensor and mode against the library. Errors: unknown sensor or
/// mode (the message lists the valid ids). Warnings: a distance of interest outside the
/// mode's [min, max] range, where the mount sees nothing.
model::Diagnostics check_rig_references(const model::Rig& rig, const model::SensorLibrary& library);

}  // namespace rigdesign::io
