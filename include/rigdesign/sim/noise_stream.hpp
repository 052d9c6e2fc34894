#pragma once
/// Seeding of the simulated sensors' noise: every sensor draws from its own stream, so adding
/// or removing one sensor leaves the others' noise as it was, and one seed fixes a whole run.
#include <cstddef>
#include <cstdint>
#include <random>

namespace rigdesign::sim {

/// The noise stream of the sensor at `sensor_index` (its mount's index in the rig) for a
/// run seeded with `seed`.
std::mt19937_64 noise_stream(std::uint64_t seed, std::size_t sensor_index);

}  // namespace rigdesign::sim
