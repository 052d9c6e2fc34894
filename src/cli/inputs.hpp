#pragma once
// Loads what a rig subcommand works on: the rig, the sensor library it refers to and its
// requirements, reporting every problem of all three at once.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/scene.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::cli {

struct RigInputs {
  model::Rig rig;
  model::SensorLibrary library;
  std::optional<model::Requirements> requirements;
  std::vector<model::Diagnostic> warnings;
};

/// `sensors_path` and `requirements_path` override what the rig file names when not empty.
/// Throws InputError with every error found (and the warnings).
RigInputs load_rig_inputs(const std::string& rig_path, const std::string& sensors_path,
                          const std::string& requirements_path);

/// Every file `inputs` were read from (rig, sensor library, requirements, robot
/// description): what an output folder must not hold.
std::vector<std::string> files_read(const RigInputs& inputs);

/// The sensor library a catalog uses: `sensors_path` when not empty, else the catalog's own
/// `sensor_library` (an error at that field when it does not exist), else the bundled one.
model::SensorLibrary load_catalog_library(const model::Catalog& catalog,
                                          const std::string& sensors_path);

/// `--scene`: a bundled generator's name (office, corridor, ...; `seed` places its furniture)
/// or a scene file (rigs/README.md, a YAML placing mesh files). Throws InputError naming
/// `--scene` for an unknown name or a missing file, and the file's own findings.
model::Scene load_scene_option(const std::string& scene, std::uint64_t seed);

/// A short name for output folders: the generator's name, or the scene file's stem.
std::string scene_label(const std::string& scene);

}  // namespace rigdesign::cli
