// Fuzz target: a PCD cloud (ascii, binary, binary_compressed with LZF).
#include "fuzz_input.hpp"
#include "io/cloud/cloud_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rigdesign::fuzz::expect_input_errors([&] {
    rigdesign::io::CloudReadReport report;
    rigdesign::io::parse_pcd("fuzz.pcd", rigdesign::fuzz::as_text(data, size), report);
  });
}
