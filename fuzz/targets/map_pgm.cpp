// Fuzz target: the PGM image of a map_server map (occupancy --map), read through a fixed
// map YAML that names it.
#include <fstream>

#include "fuzz_input.hpp"
#include "rigdesign/io/maps/map_files.hpp"

namespace {

std::string map_yaml() {
  const std::string path = rigdesign::fuzz::scratch_path("map.yaml");
  std::ofstream(path) << "image: map.pgm\nresolution: 0.05\norigin: [-1.0, -2.0, 0.0]\n"
                         "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string yaml = map_yaml();
  rigdesign::fuzz::input_file(data, size, "map.pgm");
  return rigdesign::fuzz::expect_input_errors([&] { rigdesign::io::read_map_files(yaml); });
}
