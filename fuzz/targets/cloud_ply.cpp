// Fuzz target: a PLY cloud (ascii, binary little and big endian).
#include "fuzz_input.hpp"
#include "io/cloud/cloud_formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rigdesign::fuzz::expect_input_errors([&] {
    rigdesign::io::CloudReadReport report;
    rigdesign::io::parse_ply("fuzz.ply", rigdesign::fuzz::as_text(data, size), report);
  });
}
