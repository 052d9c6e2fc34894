#include "rigdesign/sim/rig_simulation.hpp"

#include <random>

#include "rigdesign/sim/noise_stream.hpp"

namespace rigdesign::sim {

std::vector<model::PointCloud> simulate_mount(const model::Scene& scene, const model::Mount& mount,
                                              const model::SensorMode& mode,
                                              std::size_t mount_index, int frames,
                                              std::uint64_t seed,
                                              const SimulationSettings& settings,
                                              std::span<const double> free_ranges) {
  std::mt19937_64 rng = noise_stream(seed, mount_index);
  const std::vector<model::Vec3> rays = ray_pattern(mode);
  const model::Pose3 T_world_sensor = scene.T_world_robot * mount.T_robot_sensor;
  const model::Pose3 T_robot_world = scene.T_world_robot.inverse();
  std::vector<model::PointCloud> clouds;
  const bool static_scene = scene.moving.empty();
  std::optional<RayCaster> still;
  if (static_scene) still.emplace(scene.at(0.0));
  for (int k = 0; k < frames; ++k) {
    const double t = k / mode.frequency;
    std::optional<RayCaster> moving;
    if (!static_scene) moving.emplace(scene.at(t));
    model::PointCloud cloud = simulate_frame(static_scene ? *still : *moving, mode, rays,
                                             T_world_sensor, settings, rng, free_ranges);
    if (!settings.sensor_frame) {  // world frame -> robot frame
      const Eigen::Isometry3f transform = T_robot_world.cast<float>();
      for (model::Point3f& p : cloud.points) p = transform * p;
      cloud.origin = mount.T_robot_sensor.translation().cast<float>();
      cloud.orientation = Eigen::Quaternionf(mount.T_robot_sensor.linear().cast<float>());
    }
    clouds.push_back(std::move(cloud));
  }
  return clouds;
}

}  // namespace rigdesign::sim
