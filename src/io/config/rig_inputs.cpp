// What a rig subcommand works on, loaded together so that every problem is reported at once.
#include "rigdesign/io/config/rig_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/rig_references.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {
namespace {

// A file named by the rig that does not exist is the rig's error, at the naming field.
bool exists_or_report(const std::string& path, const model::SourceLocation& named_at,
                      const std::string& field, model::Diagnostics& diagnostics) {
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) return true;
  diagnostics.error(named_at, field, "names '" + path + "', which does not exist",
                    "a path relative to the rig file");
  return false;
}

template <typename Load>
auto load_collecting(Load load, model::Diagnostics& diagnostics)
    -> std::optional<decltype(load())> {
  try {
    return load();
  } catch (const model::InputError& error) {
    for (const model::Diagnostic& diagnostic : error.diagnostics()) diagnostics.add(diagnostic);
    return std::nullopt;
  }
}

}  // namespace

std::vector<std::string> files_read(const RigInputs& inputs) {
  std::vector<std::string> files = {inputs.rig.file, inputs.library.file};
  if (inputs.requirements) files.push_back(inputs.requirements->file);
  if (inputs.rig.robot) files.push_back(inputs.rig.robot->description);
  return files;
}

RigInputs load_rig_inputs(const std::string& rig_path, const std::string& sensors_path,
                          const std::string& requirements_path) {
  RigInputs inputs;
  inputs.rig = load_rig(rig_path);
  model::Diagnostics diagnostics;
  for (const model::Diagnostic& warning : inputs.rig.load_warnings) diagnostics.add(warning);
  const std::string library_path = locate_sensor_library(inputs.rig, sensors_path);
  std::optional<model::SensorLibrary> library;
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
    if (inputs.requirements) {
      for (const model::Diagnostic& warning : inputs.requirements->load_warnings)
        diagnostics.add(warning);
    }
  }
  // The requirements state how high the area to perceive reaches; a rig's own value yields.
  if (inputs.requirements && inputs.requirements->area_height) {
    const double wanted = *inputs.requirements->area_height;
    if (inputs.rig.body.area_height && std::abs(*inputs.rig.body.area_height - wanted) > 1e-9) {
      diagnostics.warning(inputs.requirements->area_height_where, "area_height",
                          "overrides the rig's area_height " +
                              model::format_number(*inputs.rig.body.area_height) + " m",
                          "one area_height, in the requirements");
    }
    inputs.rig.body.area_height = wanted;
  }
  if (library) {
    inputs.library = std::move(*library);
    const model::Diagnostics references = check_rig_references(inputs.rig, inputs.library);
    for (const model::Diagnostic& diagnostic : references.items()) diagnostics.add(diagnostic);
  }
  diagnostics.throw_if_errors();
  inputs.warnings = diagnostics.items();
  return inputs;
}

model::SensorLibrary load_catalog_library(const model::Catalog& catalog,
                                          const std::string& sensors_path) {
  std::string path = sensors_path;
  if (path.empty() && !catalog.sensor_library.empty()) {
    path = resolve_beside(catalog.file, catalog.sensor_library);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
      throw model::InputError(model::Diagnostic{catalog.sensor_library_where, "sensor_library",
                                                "names '" + path + "', which does not exist",
                                                "a path relative to the catalog file"});
    }
  }
  return load_sensor_library(path.empty() ? bundled_sensor_library() : path);
}

}  // namespace rigdesign::io
