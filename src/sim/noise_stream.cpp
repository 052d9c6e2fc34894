#include "rigdesign/sim/noise_stream.hpp"

namespace rigdesign::sim {

std::mt19937_64 noise_stream(std::uint64_t seed, std::size_t sensor_index) {
  // seed_seq mixes all 64 bits of the seed with the index; mt19937_64's sequence for a given
  // seed_seq is fixed by the standard, so runs repeat across standard libraries.
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(sensor_index)};
  return std::mt19937_64(sequence);
}

}  // namespace rigdesign::sim
