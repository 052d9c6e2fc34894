#pragma once
/// Pass-Through: keeps the points whose coordinate on one axis lies in [min, max]
/// (paper 1: [A, B] = [-10, 10] cm on z), or outside it when `negative`.
#include "rigdesign/model/filter_params.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

model::PointCloud pass_through(const model::PointCloud& cloud,
                               const model::PassThroughParams& params = {});

/// Indices of the points pass_through would keep.
std::vector<std::uint32_t> pass_through_indices(const model::PointCloud& cloud,
                                                const model::PassThroughParams& params);

}  // namespace rigdesign::filters
