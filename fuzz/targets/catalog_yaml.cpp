// Fuzz target: a catalog of slots and options, pose ranges included (rigs/catalogs/*.yaml).
#include "fuzz_input.hpp"
#include "rigdesign/io/config/catalog_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "catalog.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_catalog(path); });
}
