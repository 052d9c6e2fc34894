// Fuzz target: an emitter ground-truth file (localize --truth), CSV.
#include "fuzz_input.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(rigdesign::fuzz::as_text(data, size));
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::io::parse_emitter_truth(text, "truth.csv"); });
}
