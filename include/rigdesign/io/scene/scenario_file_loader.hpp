#pragma once
/// A user's own robot-in-the-loop scenario for `rigdesign costmap --scenario FILE.yaml`: a scene
/// file (docs/scene_files.md), where the robot starts, the goals it is sent to, the floor drops
/// it must not drive off and the sensing settings the scene needs (docs/costmap_scenarios.md
/// gives the schema).
#include <string>

#include "rigdesign/scenarios/scenario_library.hpp"

namespace rigdesign::io {

/// Loads the scenario file at `yaml_path` and the scene file it names (relative to its
/// folder). Throws InputError listing every problem found (file:line:column, field, expected
/// form), including those of the scene file and its meshes.
scenarios::ScenarioDefinition load_scenario_file(const std::string& yaml_path);

/// Whether `--scenario` names a file rather than a bundled scenario: it ends in .yaml or .yml.
bool is_scenario_file(const std::string& name);

}  // namespace rigdesign::io
