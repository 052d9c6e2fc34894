#include "rigdesign/deploy/deployment.hpp"

namespace rigdesign::deploy {

Deployment plan_deployment(const model::Rig& rig, const model::SensorLibrary& library,
                           const model::Requirements* requirements, const DeployOptions& options) {
  return {sensor_frames(rig, library, options.parent),
          costmap_config(rig, library, requirements, options), self_filters(rig, library)};
}

}  // namespace rigdesign::deploy
