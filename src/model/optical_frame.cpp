#include "rigdesign/model/optical_frame.hpp"

namespace rigdesign::model {

Pose3 T_sensor_optical() {
  Pose3 pose = Pose3::Identity();
  // Columns: the optical axes x (right), y (down), z (forward) in the sensor frame.
  pose.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  return pose;
}

}  // namespace rigdesign::model
