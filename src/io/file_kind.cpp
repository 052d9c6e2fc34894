#include "rigdesign/io/file_kind.hpp"

#include "rigdesign/io/config/yaml_reader.hpp"

namespace rigdesign::io {

FileKind detect_file_kind(const std::string& path) {
  const YAML::Node root = io::load_yaml_file(path);
  if (root.IsMap()) {
    if (root["slots"].IsDefined()) return FileKind::catalog;
    if (root["sensors"].IsDefined()) return FileKind::sensor_library;
    if (root["mounts"].IsDefined()) return FileKind::rig;
    if (root["range"].IsDefined()) return FileKind::requirements;
    if (root["steps"].IsDefined()) return FileKind::policy;
  }
  throw model::InputError(model::Diagnostic{
      {path, 1, 1},
      "(document)",
      root.IsMap() ? "is neither a sensor library, a rig nor requirements" : "is not a YAML map",
      "a map with top-level `sensors` (library), `mounts` (rig), "
      "`range` (requirements), `slots` (catalog) or `steps` (policy)"});
}

std::string to_string(FileKind kind) {
  switch (kind) {
    case FileKind::sensor_library: return "sensor library";
    case FileKind::rig: return "rig";
    case FileKind::requirements: return "requirements";
    case FileKind::catalog: return "catalog";
    case FileKind::policy: return "relaxation policy";
  }
  return "?";
}

}  // namespace rigdesign::io
