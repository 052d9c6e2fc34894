// Fuzz target: a costmap scenario file (rigs/scenes/*/*.scenario.yaml); the scene file it
// names is fuzzed by scene_yaml (here it is missing, beside the fuzzer's temporary file).
#include "fuzz_input.hpp"
#include "rigdesign/io/scene/scenario_file_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "goals.scenario.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_scenario_file(path); });
}
