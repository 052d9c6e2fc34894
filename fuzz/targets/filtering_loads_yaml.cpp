// Fuzz target: a measured filtering-load table (metrics --filtering-loads).
#include "fuzz_input.hpp"
#include "rigdesign/io/config/filtering_loads_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "loads.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_filtering_loads(path); });
}
