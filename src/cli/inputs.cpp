#include "inputs.hpp"

#include <algorithm>
#include <filesystem>

#include "rigdesign/io/scene/scene_file_loader.hpp"
#include "rigdesign/metrics/mount_placement_verdicts.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/sim/scene_library.hpp"

namespace rigdesign::cli {

namespace {

bool names_a_file(const std::string& scene) {
  const std::string extension = std::filesystem::path(scene).extension().string();
  return extension == ".yaml" || extension == ".yml" || scene.find('/') != std::string::npos;
}

}  // namespace

RigInputs load_rig_inputs(const std::string& rig_path, const std::string& sensors_path,
                          const std::string& requirements_path, std::ostream* say) {
  RigInputs inputs = io::load_rig_inputs(rig_path, sensors_path, requirements_path);
  for (model::Diagnostic& warning : metrics::placement_warnings(inputs.rig, inputs.library)) {
    if (say != nullptr) *say << warning.message() << '\n';
    inputs.warnings.push_back(std::move(warning));
  }
  return inputs;
}

model::Scene load_scene_option(const std::string& scene, std::uint64_t seed) {
  if (names_a_file(scene)) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(scene, error)) {
      throw model::InputError(
          model::Diagnostic{{"(command line)", 0, 0},
                            "--scene",
                            "'" + scene + "' does not exist",
                            "a bundled scene name or a scene file (rigs/README.md)"});
    }
    return io::load_scene_file(scene);
  }
  const auto& names = sim::scene_names();
  if (std::find(names.begin(), names.end(), scene) == names.end()) {
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                              "--scene",
                                              "unknown scene '" + scene + "'",
                                              model::join(names) + ", or a scene file (.yaml)"});
  }
  return sim::make_scene(scene, seed);
}

std::string scene_label(const std::string& scene) {
  return names_a_file(scene) ? std::filesystem::path(scene).stem().string() : scene;
}

}  // namespace rigdesign::cli
