// Fuzz target: a CO2 log (localize --log for gas sources, the DARPA SubT trace's form), CSV.
#include "fuzz_input.hpp"
#include "rigdesign/io/logs/co2_log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(rigdesign::fuzz::as_text(data, size));
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::io::parse_co2_log(text, "co2.csv"); });
}
