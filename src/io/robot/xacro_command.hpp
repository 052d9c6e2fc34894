#pragma once
/// Runs ROS's own `xacro` executable when one is on PATH: the reference implementation, so a
/// ROS user's description expands exactly as their launch files expand it.
#include <map>
#include <optional>
#include <string>

#include "rigdesign/model/source_location.hpp"

namespace rigdesign::io {

/// The path of an executable named xacro on PATH, or nothing.
std::optional<std::string> find_xacro_executable();

/// `xacro PATH name:=value ...` in a minimal environment (xacro_environment.hpp) plus the
/// rig's accepted `environment`, output to a private mkdtemp folder; returns its
/// output (the URDF text). Throws InputError at `named_at` with xacro's own message when it
/// fails.
std::string run_xacro(const std::string& executable, const std::string& path,
                      const std::map<std::string, std::string>& args,
                      const std::map<std::string, std::string>& environment,
                      const model::SourceLocation& named_at);

}  // namespace rigdesign::io
