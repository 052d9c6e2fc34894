#pragma once
/// REP-103's two frames of a camera: the sensor (body) frame rigdesign mounts by (x forward
/// along the optical axis, y left, z up) and the optical frame drivers publish clouds in
/// (z forward, x right, y down).
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// Maps optical-frame points into the sensor frame: x_sensor = z_optical, y_sensor =
/// -x_optical, z_sensor = -y_optical. A pure rotation.
Pose3 T_sensor_optical();

}  // namespace rigdesign::model
