#pragma once
/// The sensors a robot description declares for Gazebo: every `<sensor>` inside a
/// `<gazebo reference="link">` element of the expanded description (issue 52 item 5). Both
/// SDFormat spellings are read (`<ray>` of Gazebo Classic, `<lidar>` of gz sim). A number that
/// does not read is left out with a warning naming its line: these elements configure the
/// simulator only, so they never stop a rig from loading.
#include <vector>

#include "rigdesign/model/description_sensor.hpp"
#include "rigdesign/model/input_error.hpp"
#include "xml_tree.hpp"

namespace rigdesign::io {

std::vector<model::DescriptionSensor> description_sensors(const xml::Node& robot,
                                                          std::vector<model::Diagnostic>& warnings);

}  // namespace rigdesign::io
