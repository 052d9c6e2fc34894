#pragma once
/// What of a rig file may reach the external `xacro` process. A rig file arrives in pull
/// requests and is checked in CI, so it must not be able to run code: its `env` may set only
/// plain variables a description reads with $(optenv)/$(env), never one that changes how a
/// program starts (PYTHONPATH, LD_PRELOAD, PATH, ...), and its `args` only xacro argument
/// names (a name such as `-o` would become an option of xacro's command line).
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rigdesign::io {

/// Why `name` may not be set by a rig's robot.env, or nothing when it may.
std::optional<std::string> refused_environment_name(const std::string& name);

/// Why `name` is not a xacro argument name (letters, digits, underscores), or nothing.
std::optional<std::string> refused_argument_name(const std::string& name);

/// The environment of the xacro process, as NAME=value strings: the few variables of this
/// process that a ROS installation needs to run xacro (PATH, HOME, PYTHONPATH,
/// AMENT_PREFIX_PATH, ROS_PACKAGE_PATH, ROS_DISTRO, ROS_VERSION, ROS_PYTHON_VERSION,
/// LD_LIBRARY_PATH, LANG, LC_ALL), then the rig's variables that refused_environment_name
/// accepts (others are left out; the rig loader has already refused them).
std::vector<std::string> xacro_process_environment(
    const std::map<std::string, std::string>& rig_environment);

}  // namespace rigdesign::io
