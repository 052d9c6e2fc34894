// Fuzz target: a .obj mesh read by rigdesign's own reader (scene objects, robot bodies).
#include "fuzz_input.hpp"
#include "io/mesh/mesh_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::io::parse_obj_mesh("fuzz.obj", rigdesign::fuzz::as_text(data, size)); });
}
