#pragma once
#include <string>

namespace rigdesign::io {

enum class FileKind { sensor_library, rig, requirements, catalog, policy };

/// Tells what a YAML file is from its top-level keys: `slots` (a candidate catalog),
/// `sensors` (a sensor library), `mounts` (a rig), `range` (application requirements) or
/// `steps` (a relaxation policy). Throws InputError when the file
/// cannot be read, is not YAML, or is none of these.
FileKind detect_file_kind(const std::string& path);

std::string to_string(FileKind kind);

}  // namespace rigdesign::io
