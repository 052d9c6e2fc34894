#include "rigdesign/sim/robot_occlusion.hpp"

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"

namespace rigdesign::sim {

std::vector<double> robot_free_ranges(const model::Rig& rig, const model::SensorLibrary& library,
                                      const model::Mount& mount, const model::SensorMode& mode,
                                      const std::vector<model::Vec3>& rays) {
  const geometry::BodyOccluder body(rig.body);
  // No deployed limits: they shape a costmap, not what the sensor physically measures.
  const geometry::MountedFov fov(mode, mount.T_robot_sensor, body, mount.housing_link,
                                 model::MountLimits{},
                                 geometry::housings_around(rig, library, mount.id));
  std::vector<double> free_ranges;
  free_ranges.reserve(rays.size());
  const model::Mat3 R_robot_sensor = mount.T_robot_sensor.linear();
  for (const model::Vec3& ray : rays)
    free_ranges.push_back(fov.robot_free_range(R_robot_sensor * ray));
  return free_ranges;
}

}  // namespace rigdesign::sim
