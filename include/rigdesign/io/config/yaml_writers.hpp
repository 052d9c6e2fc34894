#pragma once
/// Rig and requirement files as `select` writes them, in the formats the loaders read back
/// (rigs/README.md), so `rigdesign check` accepts what `select` chose.
#include <string>

#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

/// `sensor_library` and `requirements` are written as given (paths relative to the file);
/// `comment` becomes the header comment, one "# " line per line. A rig with a robot
/// description names it (and its package paths) relative to `folder`, where the file goes,
/// with its args, env, base link and area_height; the body is then the description's, and a
/// mount placed on a description link keeps `urdf_link`.
std::string rig_to_yaml(const model::Rig& rig, const std::string& sensor_library,
                        const std::string& requirements, const std::string& comment,
                        const std::string& folder = ".");

std::string requirements_to_yaml(const model::Requirements& requirements,
                                 const std::string& comment);

}  // namespace rigdesign::io
