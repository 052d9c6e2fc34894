// Fuzz target: a relaxation policy (rigs/policies/*.yaml).
#include "fuzz_input.hpp"
#include "rigdesign/io/config/policy_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "policy.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_policy(path); });
}
