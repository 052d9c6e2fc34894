#pragma once
/// Statistical Outlier Removal with PCL's semantics (paper 1: N = 10 neighbours, M = 1):
/// each point's mean distance to its N nearest neighbours; points farther than the mean of
/// those distances plus M sample standard deviations are removed. The neighbour search is a
/// uniform grid instead of a k-d tree: filtered clouds have a known, even spacing.
#include <cstdint>
#include <vector>

#include "rigdesign/model/filter_params.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

/// Indices of the points kept, in input order.
std::vector<std::uint32_t> statistical_outlier_inliers(
    const model::PointCloud& cloud, const model::StatisticalOutlierParams& params = {});

model::PointCloud statistical_outlier_removal(const model::PointCloud& cloud,
                                              const model::StatisticalOutlierParams& params = {});

/// The cloud's points at `indices`, keeping origin and orientation.
model::PointCloud select_points(const model::PointCloud& cloud,
                                const std::vector<std::uint32_t>& indices);

}  // namespace rigdesign::filters
