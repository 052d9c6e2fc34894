#pragma once
/// The rig in gz sim (issue 34): `sensors.gazebo.xacro`, a macro of `<gazebo reference>`
/// blocks holding one SDF `<sensor>` per mount, and `bridge.yaml`, the ros_gz_bridge
/// configuration that brings each sensor's data to the ROS topic nav2 reads. Element names and
/// the bridge's schema: docs/gazebo.md (with the SDFormat, gz-sensors and ros_gz sources).
#include <string>
#include <vector>

#include "rigdesign/deploy/gazebo_sensors.hpp"

namespace rigdesign::deploy {

std::string sensors_gazebo_xacro_text(const std::vector<deploy::GazeboSensor>& sensors,
                                      const std::string& header);

std::string gz_bridge_yaml_text(const std::vector<deploy::GazeboSensor>& sensors,
                                const std::string& header);

}  // namespace rigdesign::deploy
