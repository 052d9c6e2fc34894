#pragma once
/// RANSAC plane fit (paper 1: I = 100 iterations, T = 3 cm), as PCL's SACSegmentation with
/// a plane model: the hypothesis with most inliers, refined by least squares on its inliers,
/// inliers selected again. Seeded: the same seed gives the same plane.
#include <cstdint>
#include <optional>
#include <vector>

#include "rigdesign/model/filter_params.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::filters {

struct PlaneFit {
  bool found = false;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, z >= 0 when possible
  double offset = 0.0;                                ///< plane: normal . p + offset = 0
  std::vector<std::uint32_t> inliers;                 ///< indices into the searched points
  int hypotheses = 0;                                 ///< samples drawn before stopping
};

/// Fits a plane to `cloud.points[subset[i]]` (all points when `subset` is null); inliers
/// are indices into the cloud.
PlaneFit fit_plane_ransac(const model::PointCloud& cloud,
                          const model::RansacPlaneParams& params = {},
                          const std::vector<std::uint32_t>* subset = nullptr);

/// Indices of the cloud's points within `threshold` of the plane.
std::vector<std::uint32_t> points_near_plane(const model::PointCloud& cloud, const PlaneFit& plane,
                                             double threshold);

}  // namespace rigdesign::filters
