// Fuzz target: a Clearpath robot.yaml (`clearpath-import`): its sensors section.
#include "fuzz_input.hpp"
#include "rigdesign/deploy/clearpath/clearpath_sensors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "robot.yaml");
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::deploy::read_clearpath_robot(path); });
}
