#pragma once
#include <string>

#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

/// Reads a rig file (schema in rigs/README.md). Sensor and mode references are only read
/// here; check_rig_references() resolves them against a library. Throws InputError.
model::Rig load_rig(const std::string& path);

}  // namespace rigdesign::io
