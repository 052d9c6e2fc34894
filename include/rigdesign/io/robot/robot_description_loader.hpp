#pragma once
/// Robot descriptions as ROS ships them: a URDF, or a xacro expanded first (by the `xacro`
/// executable when one is on PATH, as a ROS user has it, else by the built-in expander),
/// with `$(find PKG)` and `package://PKG/...` resolved through the rig's package paths,
/// ROS_PACKAGE_PATH and AMENT_PREFIX_PATH. Links are placed with every joint at zero;
/// collision meshes are read with assimp.
#include <map>
#include <string>
#include <vector>

#include "rigdesign/model/robot_description.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::io {

struct RobotDescriptionRequest {
  std::string path;                                ///< .urdf, .xacro or .urdf.xacro
  std::map<std::string, std::string> args;         ///< xacro arguments (name:=value)
  std::map<std::string, std::string> environment;  ///< for $(optenv) / $(env), before the process's
  std::vector<std::string> package_paths;          ///< folders holding packages, absolute
  enum class Expander { automatic, builtin, external } expander = Expander::automatic;
  bool load_meshes = true;                  ///< false: poses only (collision meshes are not opened)
  model::SourceLocation named_at;           ///< where the rig names the description
  std::string field = "robot.description";  ///< its field, for messages
};

/// Throws InputError naming the description file and line (built-in expander) or the
/// rig's field, with what was not understood.
model::RobotDescription load_robot_description(const RobotDescriptionRequest& request);

/// Whether the file needs xacro: its name ends in .xacro or it declares the xacro namespace.
bool is_xacro_file(const std::string& path);

}  // namespace rigdesign::io
