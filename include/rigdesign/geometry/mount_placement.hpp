#pragma once
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::geometry {

/// A sensor whose origin is inside the robot body would see nothing: each such mount is an
/// error at its pose. (On the body's surface is allowed.)
model::Diagnostics check_mount_placement(const model::Rig& rig);

}  // namespace rigdesign::geometry
