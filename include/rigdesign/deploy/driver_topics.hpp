#pragma once
/// The topic each mount's data arrives on (issue 30 item 5): the rig's `ros: {topic}`, or
/// the driver's topic under the rig's `ros: {namespace}`, or an explicit `export --scan-topic
/// / --cloud-topic` template, or the driver's own topic (sensors.yaml `ros2`) under the
/// mount's id as namespace when two mounts' drivers would publish the same one, or, for a
/// sensor without a known driver, /{mount}/scan or /{mount}/points. Each with a note saying
/// how the driver must run to publish there, when that differs from its default.
#include <string>
#include <vector>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

struct DriverTopic {
  std::string topic;
  std::string note;
};

/// One per mount, in mount order. Precondition: the rig's references resolve in `library`.
std::vector<DriverTopic> driver_topics(const model::Rig& rig, const model::SensorLibrary& library,
                                       const DeployOptions& options);

}  // namespace rigdesign::deploy
