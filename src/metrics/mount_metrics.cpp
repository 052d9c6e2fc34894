#include "rigdesign/metrics/mount_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::metrics {

double ray_spacing(double distance, double angular_step) {
  return distance * std::tan(angular_step);
}

MountMetrics compute_mount_metrics(const model::Mount& mount, const model::Sensor& sensor,
                                   const model::SensorMode& mode, double distance) {
  MountMetrics metrics;
  metrics.mount_id = mount.id;
  metrics.sensor_id = sensor.id;
  metrics.mode_id = mode.id;
  metrics.distance = distance;
  // The stack's throttle passes fewer frames on; the driver and the wire still carry all.
  metrics.frequency = std::min(mode.frequency, mount.throttle_hz.value_or(mode.frequency));
  metrics.point_spacing = ray_spacing(distance, mode.worst_angular_resolution());
  metrics.noise = mode.noise.sigma(distance);
  metrics.light = mode.light;
  metrics.points_per_second = mode.points_per_frame * mode.frequency;
  metrics.filtered_points_per_second = mode.points_per_frame * metrics.frequency;
  metrics.bandwidth = mode.bytes_per_frame * mode.frequency;
  metrics.driver_cpu = mode.driver_cpu.load(metrics.points_per_second);
  metrics.driver_cpu_basis = mode.driver_cpu.basis;
  metrics.price = sensor.price.usd;
  metrics.price_basis = sensor.price.basis;
  metrics.distance_in_range = distance >= mode.min_range && distance <= mode.max_range;
  return metrics;
}

}  // namespace rigdesign::metrics
