#pragma once
/// What a rig subcommand (and the studio) works on: the rig, the sensor library it refers to
/// and its requirements, loaded together so that every problem of all three is reported at
/// once, with the references between them checked. Where the mounts sit in the body is
/// judged later, with geometry (metrics' B1), not while loading.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::io {

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

}  // namespace rigdesign::io
