// Fuzz target: a nav2 costmap parameter file (costmap --params, occupancy --params).
#include "fuzz_input.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "costmap.yaml");
  return rigdesign::fuzz::expect_input_errors([&] {
    rigdesign::deploy::load_costmap_params(path, rigdesign::costmap::CostmapParams{},
                                           rigdesign::costmap::ObservationSource{});
  });
}
