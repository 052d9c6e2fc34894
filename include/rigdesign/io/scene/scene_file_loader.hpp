#pragma once
/// Scenes described by a YAML file that places meshes read from PLY, OBJ or OFF files and
/// moves some of them along waypoints or an ellipse (docs/scene_files.md gives the schema).
#include <string>

#include "rigdesign/model/scene.hpp"

namespace rigdesign::io {

/// Loads the scene file at `yaml_path`; mesh paths in it are relative to its folder. Static
/// objects come out in the world frame (scaled, then posed); moving objects in their own
/// frame (scaled, then placed by their optional `pose`) with a pose function of time [s]
/// that is deterministic and defined for every t. Throws InputError listing every problem
/// found (file:line:column, field, expected form), including those inside the mesh files.
model::Scene load_scene_file(const std::string& yaml_path);

}  // namespace rigdesign::io
