#pragma once
// Clouds for the filter tests and the answers they are checked against.
#include <cstdint>
#include <random>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::test {

model::PointCloud cloud_of(std::vector<model::Point3f> points);

/// A floor patch on a regular grid with Gaussian height noise.
std::vector<model::Point3f> noisy_floor(double size, double spacing, double sigma,
                                        std::mt19937& rng);

/// SOR's inliers by brute force: PCL's definition (mean distance to the k nearest others,
/// kept when within mean + 1 sample standard deviation), written independently.
std::vector<std::uint32_t> brute_force_inliers(const std::vector<model::Point3f>& points, int k);

}  // namespace rigdesign::test
