#pragma once
/// Rig and requirement files as `select` writes them, in the formats the loaders read back
/// (rigs/README.md), so `rigdesign check` accepts what `select` chose.
#include <string>

#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

/// How a file written into `folder` names `path`: relative when `path` lies inside the
/// folder (the two move together), absolute otherwise, so that moving the folder does not
/// break the reference (a relative `../../x/sensors.yaml` would).
std::string path_seen_from(const std::string& path, const std::string& folder);

/// `sensor_library` and `requirements` are written as given (paths relative to the file);
/// `comment` becomes the header comment, one "# " line per line. A rig with a robot
/// description names it (and its package paths) as path_seen_from `folder`, where the file goes,
/// with its args, env, base link and area_height; the body is then the description's, and a
/// mount placed on a description link keeps `urdf_link`.
std::string rig_to_yaml(const model::Rig& rig, const std::string& sensor_library,
                        const std::string& requirements, const std::string& comment,
                        const std::string& folder = ".");

std::string requirements_to_yaml(const model::Requirements& requirements,
                                 const std::string& comment);

}  // namespace rigdesign::io
