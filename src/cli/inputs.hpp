#pragma once
// What subcommands load from their options: a rig with its library and requirements, and a
// scene given by name or file.
#include <cstdint>
#include <ostream>
#include <string>

#include "rigdesign/io/config/rig_inputs.hpp"
#include "rigdesign/model/scene.hpp"

namespace rigdesign::cli {

using io::files_read;
using io::load_catalog_library;
using io::RigInputs;

/// io::load_rig_inputs, and a warning for each mount buried in the body (metrics' B1, which
/// `check` judges), added to the inputs' warnings and, with `say`, written there: the commands
/// that compute with a rig say so, then show what it sees.
RigInputs load_rig_inputs(const std::string& rig_path, const std::string& sensors_path,
                          const std::string& requirements_path, std::ostream* say = nullptr);

/// `--scene`: a bundled generator's name (office, corridor, ...; `seed` places its furniture)
/// or a scene file (rigs/README.md, a YAML placing mesh files). Throws InputError naming
/// `--scene` for an unknown name or a missing file, and the file's own findings.
model::Scene load_scene_option(const std::string& scene, std::uint64_t seed);

/// A short name for output folders: the generator's name, or the scene file's stem.
std::string scene_label(const std::string& scene);

}  // namespace rigdesign::cli
