#include "rigdesign/metrics/resultant.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/model/units.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

model::SensorMode mode_of(const std::string& id, double frequency, double step_deg, double noise_a,
                          bool sunlight) {
  model::SensorMode mode;
  mode.id = id;
  mode.frequency = frequency;
  mode.min_range = 0.1;
  mode.max_range = 10;
  mode.angular_resolution_h = model::deg_to_rad(step_deg);
  mode.angular_resolution_v = model::deg_to_rad(step_deg);
  mode.points_per_frame = 1000;
  mode.bytes_per_frame = 2000;
  mode.noise.a = noise_a;
  mode.light = {true, true, sunlight};
  mode.driver_cpu.cores = 0.1;
  return mode;
}

model::Mount mount_of(const std::string& id, const std::string& mode) {
  model::Mount mount;
  mount.id = id;
  mount.sensor_id = "s";
  mount.mode_id = mode;
  return mount;
}

}  // namespace

TEST_CASE("resultant F, R, N, L take the worst sensor and name it, ties included") {
  model::SensorLibrary library;
  model::Sensor sensor;
  sensor.id = "s";
  sensor.price.usd = 100;
  sensor.modes = {mode_of("slow", 10, 1.0, 0.02, true), mode_of("fast", 30, 0.5, 0.05, false)};
  library.sensors.push_back(sensor);

  model::Rig rig;
  rig.distance_of_interest = 2.0;
  rig.mounts = {mount_of("a", "slow"), mount_of("b", "fast"), mount_of("c", "slow")};
  rig.mounts[2].distance_of_interest = 1.0;

  const metrics::ResultantMetrics metrics = metrics::compute_resultant(rig, library);
  CHECK(metrics.frequency.value == 10);
  CHECK(metrics.frequency.mounts == std::vector<std::string>{"a", "c"});
  // a: 2 m * tan 1 deg = 34.91 mm; b: 2 m * tan 0.5 deg = 17.45 mm; c: 1 m * tan 1 deg = 17.46 mm.
  CHECK_THAT(metrics.point_spacing.value, WithinAbs(0.0349098, 1e-6));
  CHECK(metrics.point_spacing.mounts == std::vector<std::string>{"a"});
  CHECK(metrics.noise.value == 0.05);
  CHECK(metrics.noise.mounts == std::vector<std::string>{"b"});
  CHECK(metrics.light_for(model::LightCondition::dark).immune);
  CHECK_FALSE(metrics.light_for(model::LightCondition::sunlight).immune);
  CHECK(metrics.light_for(model::LightCondition::sunlight).failing_mounts ==
        std::vector<std::string>{"b"});
  // B = 2000 B * (10 + 30 + 10) Hz; U_p = 3 * 0.1; C_s = 3 * 100.
  CHECK(metrics.bandwidth == 100000);
  CHECK_THAT(metrics.driver_cpu, WithinAbs(0.3, 1e-12));
  CHECK(metrics.sensor_cost == 300);
}
