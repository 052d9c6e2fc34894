// Fuzz target: a SubT artifact list (JSON read by the YAML parser).
#include "fuzz_input.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "artifacts.json");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::read_artifacts(path); });
}
