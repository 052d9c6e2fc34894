// Fuzz target: an RSSI log (localize --log), CSV.
#include "rigdesign/io/logs/rssi_csv.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(rigdesign::fuzz::as_text(data, size));
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::io::parse_rssi_csv(text, "rssi.csv"); });
}
