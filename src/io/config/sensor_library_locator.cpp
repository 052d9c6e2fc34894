#include "rigdesign/io/config/sensor_library_locator.hpp"

#include <filesystem>

namespace rigdesign::io {

std::string resolve_beside(const std::string& file, const std::string& relative) {
  const std::filesystem::path path(relative);
  if (path.is_absolute()) return path.string();
  return (std::filesystem::path(file).parent_path() / path).lexically_normal().string();
}

std::string bundled_sensor_library() {
  return (std::filesystem::path(RIGDESIGN_DATA_DIR) / "sensors.yaml").string();
}

std::string locate_sensor_library(const model::Rig& rig, const std::string& explicit_path) {
  if (!explicit_path.empty()) return explicit_path;
  if (!rig.sensor_library.empty()) return resolve_beside(rig.file, rig.sensor_library);
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path rig_folder = fs::absolute(fs::path(rig.file), error).parent_path();
  for (fs::path folder = rig_folder; !error && !folder.empty(); folder = folder.parent_path()) {
    const fs::path candidate = folder / "sensors.yaml";
    std::error_code not_there;  // a missing file is the normal case, not an error
    if (fs::is_regular_file(candidate, not_there)) {
      const fs::path shown = fs::relative(candidate, fs::current_path(), not_there);
      return not_there || shown.empty() ? candidate.string() : shown.string();
    }
    if (folder == folder.root_path()) break;
  }
  return bundled_sensor_library();
}

}  // namespace rigdesign::io
