#include "inputs.hpp"

#include <algorithm>
#include <filesystem>

#include "rigdesign/geometry/mount_placement.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/rig_references.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/scene/scene_file_loader.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::cli {
namespace {

// A file named by the rig that does not exist is the rig's error, at the naming field.
bool exists_or_report(const std::string& path, const SourceLocation& named_at,
                      const std::string& field, Diagnostics& diagnostics) {
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) return true;
  diagnostics.error(named_at, field, "names '" + path + "', which does not exist",
                    "a path relative to the rig file");
  return false;
}

template <typename Load>
auto load_collecting(Load load, Diagnostics& diagnostics) -> std::optional<decltype(load())> {
  try {
    return load();
  } catch (const InputError& error) {
    for (const Diagnostic& diagnostic : error.diagnostics()) diagnostics.add(diagnostic);
    return std::nullopt;
  }
}

}  // namespace

RigInputs load_rig_inputs(const std::string& rig_path, const std::string& sensors_path,
                          const std::string& requirements_path) {
  RigInputs inputs;
  inputs.rig = load_rig(rig_path);
  Diagnostics diagnostics;
  const std::string library_path = locate_sensor_library(inputs.rig, sensors_path);
  std::optional<SensorLibrary> library;
  if (!sensors_path.empty() || inputs.rig.sensor_library.empty() ||
      exists_or_report(library_path, inputs.rig.sensor_library_where, "sensor_library",
                       diagnostics)) {
    library = load_collecting([&] { return load_sensor_library(library_path); }, diagnostics);
  }
  std::string wanted_requirements = requirements_path;
  bool requirements_readable = true;
  if (wanted_requirements.empty() && !inputs.rig.requirements.empty()) {
    wanted_requirements = resolve_beside(inputs.rig.file, inputs.rig.requirements);
    requirements_readable = exists_or_report(wanted_requirements, inputs.rig.requirements_where,
                                             "requirements", diagnostics);
  }
  if (!wanted_requirements.empty() && requirements_readable) {
    inputs.requirements =
        load_collecting([&] { return load_requirements(wanted_requirements); }, diagnostics);
  }
  if (library) {
    inputs.library = std::move(*library);
    const Diagnostics references = check_rig_references(inputs.rig, inputs.library);
    for (const Diagnostic& diagnostic : references.items()) diagnostics.add(diagnostic);
  }
  const Diagnostics placement = check_mount_placement(inputs.rig);
  for (const Diagnostic& diagnostic : placement.items()) diagnostics.add(diagnostic);
  diagnostics.throw_if_errors();
  inputs.warnings = diagnostics.items();
  return inputs;
}

SensorLibrary load_catalog_library(const Catalog& catalog, const std::string& sensors_path) {
  std::string path = sensors_path;
  if (path.empty() && !catalog.sensor_library.empty()) {
    path = resolve_beside(catalog.file, catalog.sensor_library);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
      throw InputError(Diagnostic{catalog.sensor_library_where, "sensor_library",
                                  "names '" + path + "', which does not exist",
                                  "a path relative to the catalog file"});
    }
  }
  return load_sensor_library(path.empty() ? bundled_sensor_library() : path);
}

namespace {

bool names_a_file(const std::string& scene) {
  const std::string extension = std::filesystem::path(scene).extension().string();
  return extension == ".yaml" || extension == ".yml" || scene.find('/') != std::string::npos;
}

}  // namespace

Scene load_scene_option(const std::string& scene, std::uint64_t seed) {
  if (names_a_file(scene)) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(scene, error)) {
      throw InputError(Diagnostic{{"(command line)", 0, 0},
                                  "--scene",
                                  "'" + scene + "' does not exist",
                                  "a bundled scene name or a scene file (rigs/README.md)"});
    }
    return load_scene_file(scene);
  }
  const auto& names = scene_names();
  if (std::find(names.begin(), names.end(), scene) == names.end()) {
    throw InputError(Diagnostic{{"(command line)", 0, 0},
                                "--scene",
                                "unknown scene '" + scene + "'",
                                join(names) + ", or a scene file (.yaml)"});
  }
  return make_scene(scene, seed);
}

std::string scene_label(const std::string& scene) {
  return names_a_file(scene) ? std::filesystem::path(scene).stem().string() : scene;
}

}  // namespace rigdesign::cli
