#pragma once
/// A mount the robot description already simulates (issue 52 item 5). Where the description
/// declares a Gazebo `<sensor>` inside a mount's housing (a Jackal's laser accessory, the
/// TurtleBot 4's RPLIDAR), that sensor is the mount's: the export adds no second one, which
/// libsdformat refuses when the names match ("sensor with name[front_laser] already exists")
/// and gz sim would otherwise run beside the first. What the description's sensor simulates
/// differently from the design is said, so that the engineer can align it.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/deploy/gazebo_sensors.hpp"
#include "rigdesign/model/description_sensor.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

/// The description's sensor of `mount`: the first whose origin lies in the mount's housing
/// grown by 10 mm (as far as sensors.yaml lets a data origin lie outside it), or within 5 cm of the
/// mount's data origin for a sensor without a housing; nothing when the description declares none
/// there.
std::optional<model::DescriptionSensor> description_sensor_of(const model::Rig& rig,
                                                              const model::Mount& mount,
                                                              const model::SensorLibrary& library);

/// Where gz sim publishes a sensor that sets no `<topic>`, as a pattern: its scoped name under
/// the world and the model (gz-sim src/rendering/RenderUtil.cc:1723 at 93bbf3e), which the
/// export cannot know.
std::string gz_scoped_topic(const std::string& sensor_name);

/// One phrase per way the description's sensor simulates `designed` differently: its type
/// where gz sim does not render it, rate, rays, angles, image, ranges, topic and frame.
std::vector<std::string> description_sensor_differences(const model::DescriptionSensor& own,
                                                        const GazeboSensor& designed);

}  // namespace rigdesign::deploy
