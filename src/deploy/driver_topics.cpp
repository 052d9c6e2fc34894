#include "rigdesign/deploy/driver_topics.hpp"

#include <map>
#include <string>
#include <vector>

namespace rigdesign::deploy {
namespace {

// The driver's topic under `ns` ("/scan" in "front" is "/front/scan").
std::string in_namespace(const std::string& ns, const std::string& topic) {
  return "/" + ns + (topic.front() == '/' ? topic : "/" + topic);
}

}  // namespace

std::vector<DriverTopic> driver_topics(const model::Rig& rig, const model::SensorLibrary& library,
                                       const DeployOptions& options) {
  std::map<std::string, int> uses;
  for (const model::Mount& mount : rig.mounts) {
    const model::Sensor& sensor = *library.find(mount.sensor_id);
    if (sensor.ros2 && sensor.ros2->exists && mount.ros_topic.empty() &&
        mount.ros_namespace.empty())
      ++uses[sensor.ros2->topic];
  }
  std::vector<DriverTopic> topics;
  for (const model::Mount& mount : rig.mounts) {
    const model::Sensor& sensor = *library.find(mount.sensor_id);
    const bool scan =
        library.resolved_mode(mount.sensor_id, mount.mode_id).fov.shape().is_planar_scan();
    const std::string& given = scan ? options.scan_topic : options.cloud_topic;
    const bool driver = sensor.ros2 && sensor.ros2->exists;
    if (!mount.ros_topic.empty()) {
      topics.push_back(DriverTopic{mount.ros_topic, ""});
    } else if (!given.empty()) {
      topics.push_back(DriverTopic{expand_topic(given, mount.id), ""});
    } else if (driver && !mount.ros_namespace.empty()) {
      topics.push_back(
          DriverTopic{in_namespace(mount.ros_namespace, sensor.ros2->topic),
                      "launch " + sensor.ros2->package + " in namespace " + mount.ros_namespace});
    } else if (driver && uses[sensor.ros2->topic] > 1) {
      topics.push_back(DriverTopic{in_namespace(mount.id, sensor.ros2->topic),
                                   "launch " + sensor.ros2->package + " in namespace " + mount.id +
                                       " (another mount's driver publishes " + sensor.ros2->topic +
                                       " too)"});
    } else if (driver) {
      topics.push_back(DriverTopic{sensor.ros2->topic, ""});
    } else {
      topics.push_back(
          DriverTopic{expand_topic(scan ? "/{mount}/scan" : "/{mount}/points", mount.id),
                      "no ROS 2 driver is known for " + sensor.id + ": publish there"});
    }
  }
  return topics;
}

}  // namespace rigdesign::deploy
