// Fuzz target: a sensor library (sensors.yaml).
#include "fuzz_input.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "sensors.yaml");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::load_sensor_library(path); });
}
