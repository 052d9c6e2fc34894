#pragma once
#include <string>

#include "rigdesign/model/filter_params.hpp"

namespace rigdesign::io {

/// Reads a user-defined filter pipeline:
///   name: mine
///   stages:
///     - voxel_grid: {leaf: 0.03}
///     - statistical_outlier: {neighbours: 10, std_multiplier: 1.0}
///     - floor_removal_1: {slice: {min: -0.1, max: 0.1}, ransac: {iterations: 100, threshold:
///     0.03}}
/// Every parameter is optional and defaults to the papers' value (rigs/README.md lists them).
/// Throws InputError, e.g. for an unknown stage.
model::Pipeline load_pipeline(const std::string& path);

}  // namespace rigdesign::io
