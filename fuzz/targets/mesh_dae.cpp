// Fuzz target: a .dae collision mesh of a robot description, read through assimp (the
// library is not instrumented; this target guards what rigdesign does with its output).
#include "fuzz_input.hpp"
#include "rigdesign/io/mesh/assimp_mesh_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "mesh.dae");
  return rigdesign::fuzz::expect_input_errors([&] {
    rigdesign::io::load_mesh_with_assimp(path, {"rig.yaml", 1, 1});
  });
}
