#pragma once
/// ROS 2's naming rules for what an exported file names: topics (tokens of letters, digits
/// and underscores, not starting with a digit, joined by '/', optionally absolute; design.ros2.org
/// "Topic and Service name mapping") and TF frame ids (tf2 takes any non-empty string; a
/// frame id here is printable ASCII without spaces and without a leading '/', which tf2
/// rejects, so it fits unquoted into YAML, URDF and Python).
#include <string>

namespace rigdesign::model {

bool is_topic_name(const std::string& name);
bool is_frame_id(const std::string& name);

}  // namespace rigdesign::model
