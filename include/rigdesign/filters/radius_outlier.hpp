#pragma once
/// Radius outlier removal (paper 2, section 3.2): points with fewer than N other points within
/// a radius are removed, with PCL's RadiusOutlierRemoval semantics (a neighbour at exactly the
/// radius counts; distances compared in float as PCL's search computes them). The search is a
/// uniform grid, as the statistical outlier removal's, and a point's count stops at N.
#include <cstdint>
#include <vector>

#include "rigdesign/model/filter_params.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

/// Indices of the points kept, in input order. Throws InputError (field
/// "radius_outlier.radius" or ".min_neighbours") for a radius <= 0 or a count <= 0.
std::vector<std::uint32_t> radius_outlier_inliers(const model::PointCloud& cloud,
                                                  const model::RadiusOutlierParams& params = {});

model::PointCloud radius_outlier_removal(const model::PointCloud& cloud,
                                         const model::RadiusOutlierParams& params = {});

}  // namespace rigdesign::filters
