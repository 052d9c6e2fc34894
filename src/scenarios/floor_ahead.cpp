#include "rigdesign/scenarios/floor_ahead.hpp"

#include <cmath>

#include "rigdesign/sim/sensor_simulator.hpp"

namespace rigdesign::scenarios {

double stoppable_speed(double distance, double reaction, double deceleration) {
  if (!(distance > 0.0) || !(deceleration > 0.0)) return 0.0;
  // The positive root of v^2 / (2a) + v t - d = 0.
  return deceleration *
         (-reaction + std::sqrt(reaction * reaction + 2.0 * distance / deceleration));
}

FloorAhead floor_ahead(const model::Rig& rig, const model::SensorLibrary& library,
                       const std::vector<MountTiming>& timings, double update_period,
                       double control_period, double deceleration) {
  FloorAhead best;
  best.deceleration = deceleration;
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::Sensor* sensor = library.find(mount.sensor_id);
    const model::SensorMode* mode = sensor ? sensor->find_mode(mount.mode_id) : nullptr;
    if (!mode) continue;
    const model::Vec3 origin = mount.T_robot_sensor.translation();
    const model::Mat3 R = mount.T_robot_sensor.linear();
    double farthest = 0.0;
    for (const model::Vec3& ray : sim::ray_pattern(*mode)) {
      const model::Vec3 d = R * ray;
      if (!(d.z() < 0.0) || !(origin.z() > 0.0)) continue;
      const double s = -origin.z() / d.z();
      if (s < mode->min_range || s > mode->max_range) continue;
      const model::Vec3 floor = origin + s * d;
      if (floor.x() > 0.0 && std::abs(floor.y()) <= rig.body.radius)
        farthest = std::max(farthest, floor.x());
    }
    if (farthest <= best.distance) continue;
    best.mount = mount.id;
    best.distance = farthest;
    const MountTiming& timing = timings.at(i);
    best.reaction = timing.period + timing.latency() + update_period + control_period;
  }
  best.stoppable_speed =
      stoppable_speed(best.distance - rig.body.radius, best.reaction, deceleration);
  return best;
}

}  // namespace rigdesign::scenarios
