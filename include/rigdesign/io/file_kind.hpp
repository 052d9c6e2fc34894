#pragma once
#include <string>

namespace rigdesign {

enum class FileKind { sensor_library, rig, requirements };

/// Tells what a YAML file is from its top-level keys: `sensors` (a sensor library),
/// `mounts` (a rig) or `range` (application requirements). Throws InputError when the file
/// cannot be read, is not YAML, or is none of these.
FileKind detect_file_kind(const std::string& path);

std::string to_string(FileKind kind);

}  // namespace rigdesign
