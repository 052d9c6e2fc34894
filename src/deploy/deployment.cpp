#include "rigdesign/deploy/deployment.hpp"

namespace rigdesign::deploy {

Deployment plan_deployment(const model::Rig& rig, const model::SensorLibrary& library,
                           const model::Requirements* requirements, const DeployOptions& options) {
  Deployment deployment{sensor_frames(rig, library, options.parent),
                        costmap_config(rig, library, requirements, options),
                        self_filters(rig, library),
                        {},
                        std::nullopt,
                        std::nullopt};
  // The costmap reads what the self-filters leave, not the raw data with the robot in it.
  for (std::size_t m = 0; m < deployment.self_filters.size(); ++m) {
    SourceConfig& source = deployment.costmap.sources[m];
    if (filters_anything(deployment.self_filters[m]))
      source.topic = self_filtered_topic(source.raw_topic);
  }
  deployment.gazebo = gazebo_sensors(rig, deployment.frames, deployment.costmap, library);
  if (options.stvl) deployment.stvl = stvl_layer(rig, library, deployment.costmap);
  deployment.collision_monitor =
      collision_monitor(rig, library, requirements, deployment.costmap,
                        {options.ros_distro, options.max_speed, options.processing_latency});
  return deployment;
}

}  // namespace rigdesign::deploy
