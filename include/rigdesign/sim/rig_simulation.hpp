#pragma once
/// A whole rig in a scene: the robot stands at the scene's start pose and every mount
/// records frames at its own rate; clouds come back in the robot frame (or each sensor's),
/// with the sensor origin recorded.
#include <cstdint>
#include <span>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/scene.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

namespace rigdesign::sim {

/// `frames` clouds of `mount` (mode `mode`), frame k at t = k / frequency. Deterministic
/// for a seed: each mount draws from its own stream seeded with (seed, mount index).
/// `free_ranges`: robot_free_ranges for ray_pattern(mode), what the robot hides (empty: none).
std::vector<model::PointCloud> simulate_mount(const model::Scene& scene, const model::Mount& mount,
                                              const model::SensorMode& mode,
                                              std::size_t mount_index, int frames,
                                              std::uint64_t seed,
                                              const SimulationSettings& settings = {},
                                              std::span<const double> free_ranges = {});

}  // namespace rigdesign::sim
