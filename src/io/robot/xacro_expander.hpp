#pragma once
/// The built-in xacro expander, used when no `xacro` executable is on PATH: what real robot
/// descriptions use of xacro (ROS 2's xacro 2.x semantics): xacro:property (value, default,
/// block, scope, lazy evaluation), xacro:arg and $(arg), $(find PKG), $(optenv VAR default),
/// $(env VAR), $(dirname), xacro:macro with plain, default (:=, ^, ^|), block (*) and
/// content-block (**) parameters, xacro:insert_block, xacro:include (relative to the
/// including file; never opened inside a false xacro:if), xacro:if / xacro:unless,
/// xacro:element, and ${...} Python expressions (xacro_expression.hpp). Macros see the
/// caller's properties (xacro's dynamic scoping). Every error names the xacro file and
/// line and what was not understood. One deliberate difference from xacro: <gazebo>,
/// <ros2_control> and <transmission> elements are dropped unexpanded (no geometry or frames
/// live there, and their plugins name packages a design machine need not have).
#include <map>
#include <set>
#include <string>

#include "package_locator.hpp"
#include "rigdesign/model/source_location.hpp"
#include "xml_tree.hpp"

namespace rigdesign::io {

struct XacroInput {
  std::string path;                                ///< the top-level .xacro or .urdf
  std::map<std::string, std::string> args;         ///< name:=value, as on xacro's command line
  std::map<std::string, std::string> environment;  ///< read by $(optenv) / $(env) before the
                                                   ///< process's environment
  const PackageLocator* packages = nullptr;        ///< resolves $(find PKG)
  /// When given, every variable $(optenv) or $(env) asked for is added: a rig's `env` the
  /// description never reads is a typo worth a warning (HUSKY_LASER_3D_ENABLE).
  std::set<std::string>* environment_read = nullptr;
  model::SourceLocation named_at;  ///< where the rig names the description
  /// Expand `<gazebo>`, `<ros2_control>` and `<transmission>` too (the simulation's URDF, as
  /// the tests hand it to libsdformat); by default they are left out unexpanded, so that a
  /// plugin's $(find PKG) this machine lacks does not stop a description from loading.
  bool keep_simulation = false;
  /// Expand `<gazebo reference="LINK">` only: where a description declares its sensors for the
  /// simulator; model-wide `<gazebo>` plugins and `<ros2_control>` name packages of the robot's
  /// bringup (irobot_create_control) that a design machine need not have.
  bool keep_gazebo = false;
};

/// The expanded description: a plain URDF tree whose elements keep the file and line of the
/// xacro text they came from. Throws InputError.
xml::Node expand_xacro(const XacroInput& input);

}  // namespace rigdesign::io
