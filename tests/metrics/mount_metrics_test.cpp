#include "rigdesign/metrics/mount_metrics.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/model/units.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("ray spacing is d * tan(step), paper 1's R") {
  // tan(2 deg) = 0.0349207695 (tables), times 3.5 m.
  CHECK_THAT(metrics::ray_spacing(3.5, model::deg_to_rad(2.0)), WithinAbs(0.1222227, 1e-6));
  CHECK(metrics::ray_spacing(0.0, model::deg_to_rad(2.0)) == 0.0);
}

TEST_CASE("noise model evaluates a + b d + c d^2") {
  const model::NoiseModel model{0.01, 0.002, 0.001};
  // 0.01 + 0.002 * 2 + 0.001 * 4 = 0.018
  CHECK_THAT(model.sigma(2.0), WithinAbs(0.018, 1e-15));
}

TEST_CASE("mount metrics combine a mode's datasheet values at the distance of interest") {
  model::Sensor sensor;
  sensor.id = "cam";
  sensor.price = {250.0, 2020, model::Basis::estimate, "test"};
  model::SensorMode mode;
  mode.id = "m";
  mode.frequency = 10;
  mode.min_range = 0.2;
  mode.max_range = 3.0;
  mode.angular_resolution_h = model::deg_to_rad(0.1);
  mode.angular_resolution_v = model::deg_to_rad(0.2);
  mode.points_per_frame = 240000;
  mode.bytes_per_frame = 480000;
  mode.noise = {0.0, 0.01, 0.0};
  mode.driver_cpu = {0.02, 1e-8, model::Basis::estimate, ""};
  model::Mount mount;
  mount.id = "front";

  const metrics::MountMetrics metrics = metrics::compute_mount_metrics(mount, sensor, mode, 2.0);
  CHECK(metrics.frequency == 10);
  // The coarser step sets R: 2 m * tan(0.2 deg) = 2 * 0.00349066 = 6.98 mm.
  CHECK_THAT(metrics.point_spacing, WithinAbs(0.0069813, 1e-6));
  CHECK_THAT(metrics.noise, WithinAbs(0.02, 1e-15));
  CHECK_THAT(metrics.bandwidth, WithinRel(4.8e6, 1e-12));          // 480 kB * 10 Hz
  CHECK_THAT(metrics.driver_cpu, WithinAbs(0.02 + 0.024, 1e-12));  // 1e-8 s * 2.4 M points/s
  CHECK(metrics.price == 250.0);
  CHECK(metrics.distance_in_range);
  CHECK_FALSE(metrics::compute_mount_metrics(mount, sensor, mode, 3.5).distance_in_range);
}

TEST_CASE("a single-row scanner's spacing uses its horizontal step only") {
  model::SensorMode mode;
  mode.angular_resolution_h = model::deg_to_rad(0.5);
  CHECK(mode.worst_angular_resolution() == model::deg_to_rad(0.5));
}
