#pragma once
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::geometry {

/// A sensor whose origin is inside the robot body would see nothing: each such mount is an
/// error at its pose. (On the body's surface is allowed.)
model::Diagnostics check_mount_placement(const model::Rig& rig);
/// The same against an occluder already built from `rig.body` (building one bins every
/// triangle of a description's body: the studio checks each drag step against one).
model::Diagnostics check_mount_placement(const model::Rig& rig, const BodyOccluder& body);

}  // namespace rigdesign::geometry
