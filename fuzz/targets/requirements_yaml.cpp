// Fuzz target: a requirements file (rigs/requirements/*.yaml).
#include "fuzz_input.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "requirements.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_requirements(path); });
}
