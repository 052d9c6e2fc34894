// Fuzz target: a scene file (rigs/scenes/*/*.yaml); its meshes are fuzzed by the mesh targets.
#include "fuzz_input.hpp"
#include "rigdesign/io/scene/scene_file_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "scene.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_scene_file(path); });
}
