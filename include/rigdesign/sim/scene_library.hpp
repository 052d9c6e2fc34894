#pragma once
/// The bundled synthetic scenes (DESIGN.md section 6), built by name.
#include <cstdint>
#include <string>
#include <vector>

#include "rigdesign/model/scene.hpp"

namespace rigdesign::sim {

/// "office", "corridor", "stairs", "wall_following", "cell".
const std::vector<std::string>& scene_names();

/// Builds a named scene; `seed` places the office's furniture. Throws std::invalid_argument
/// for an unknown name (the CLI checks names first).
model::Scene make_scene(const std::string& name, std::uint64_t seed);

}  // namespace rigdesign::sim
