#include "rigdesign/io/config/sensor_library_locator.hpp"

#include <cstdlib>
#include <filesystem>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

std::string resolve_beside(const std::string& file, const std::string& relative) {
  const std::filesystem::path path(relative);
  if (path.is_absolute()) return path.string();
  return (std::filesystem::path(file).parent_path() / path).lexically_normal().string();
}

namespace {

constexpr const char* kDataFolderVariable = "RIGDESIGN_DATA_DIR";

/// The running executable's folder; empty when /proc is not mounted.
std::filesystem::path executable_folder() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : executable.parent_path();
}

}  // namespace

std::string bundled_data_folder() {
  const char* variable = std::getenv(kDataFolderVariable);
  if (variable != nullptr && *variable != '\0') return variable;
  const std::filesystem::path folder = executable_folder();
  if (folder.empty()) return {};
  return (folder.parent_path() / "share" / "rigdesign").string();
}

std::string bundled_sensor_library() {
  const std::string folder = bundled_data_folder();
  const std::filesystem::path library = std::filesystem::path(folder) / "sensors.yaml";
  std::error_code not_there;
  if (!folder.empty() && std::filesystem::is_regular_file(library, not_there)) {
    return library.string();
  }
  const char* variable = std::getenv(kDataFolderVariable);
  const std::string looked =
      folder.empty() ? "no executable path (/proc/self/exe unreadable)" : library.string();
  throw model::InputError(model::Diagnostic{
      model::SourceLocation{library.string(), 0, 0}, "sensor library",
      "no bundled sensors.yaml at " + looked +
          (variable != nullptr && *variable != '\0' ? " (from $RIGDESIGN_DATA_DIR)"
                                                    : " (share/rigdesign beside the executable)"),
      "set RIGDESIGN_DATA_DIR to the folder holding sensors.yaml (e.g. "
      "<prefix>/share/rigdesign), or pass --sensors FILE"});
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
      // Shown relative to the working folder when it lies inside it, else absolute.
      const fs::path shown = fs::relative(candidate, fs::current_path(), not_there);
      const bool inside = !not_there && !shown.empty() && *shown.begin() != "..";
      return inside ? shown.string() : candidate.string();
    }
    if (folder == folder.root_path()) break;
  }
  return bundled_sensor_library();
}

}  // namespace rigdesign::io
