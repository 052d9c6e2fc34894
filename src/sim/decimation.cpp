#include "rigdesign/sim/decimation.hpp"

#include <algorithm>

namespace rigdesign::sim {

model::SensorMode decimated_mode(model::SensorMode mode, int camera_stride, int lidar_stride) {
  const bool camera = mode.is_camera();
  const int stride = std::max(1, camera ? camera_stride : lidar_stride);
  if (stride == 1) return mode;
  mode.angular_resolution_h *= stride;
  if (camera && mode.angular_resolution_v) *mode.angular_resolution_v *= stride;
  mode.points_per_frame /= static_cast<double>(camera ? stride * stride : stride);
  return mode;
}

}  // namespace rigdesign::sim
