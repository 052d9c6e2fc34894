// Fuzz target: a wall map (localize --walls), CSV.
#include "rigdesign/io/logs/walls_csv.hpp"

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(rigdesign::fuzz::as_text(data, size));
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::io::parse_walls_csv(text, "walls.csv"); });
}
