#include "rigdesign/filters/floor_removal.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/filters/statistical_outlier.hpp"

namespace rigdesign::filters {
namespace {

model::PointCloud without(const model::PointCloud& cloud,
                          const std::vector<std::uint32_t>& removed) {
  if (!std::is_sorted(removed.begin(), removed.end())) {  // RANSAC's inliers come sorted
    std::vector<std::uint32_t> sorted = removed;
    std::sort(sorted.begin(), sorted.end());
    return without(cloud, sorted);
  }
  model::PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  result.points.reserve(cloud.size() - std::min(cloud.size(), removed.size()));
  std::size_t next = 0;
  for (std::uint32_t i = 0; i < cloud.size(); ++i) {
    if (next < removed.size() && removed[next] == i) {
      ++next;
      continue;
    }
    result.points.push_back(cloud.points[i]);
  }
  return result;
}

// One pass that keeps what lies beyond `threshold` of the plane: no index list to build, sort
// and walk again as `without` needs for a subset's inliers.
model::PointCloud far_from_plane(const model::PointCloud& cloud, const PlaneFit& plane,
                                 double threshold) {
  model::PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  result.points.reserve(cloud.size());
  const Eigen::Vector3f normal = plane.normal.cast<float>();
  const float offset = static_cast<float>(plane.offset);
  const float limit = static_cast<float>(threshold);
  for (const model::Point3f& p : cloud.points) {
    if (std::abs(normal.dot(p) + offset) > limit) result.points.push_back(p);
  }
  return result;
}

}  // namespace

model::PointCloud remove_floor_1(const model::PointCloud& cloud,
                                 const model::FloorRemoval1Params& params) {
  const std::vector<std::uint32_t> slice = pass_through_indices(cloud, params.slice);
  const PlaneFit floor = fit_plane_ransac(cloud, params.ransac, &slice);
  if (!floor.found) return cloud;
  return without(cloud, floor.inliers);
}

model::PointCloud remove_floor_2(const model::PointCloud& cloud,
                                 const model::FloorRemoval2Params& params) {
  model::VoxelGridParams coarse;
  coarse.leaf = params.coarse_leaf;
  const model::PointCloud sparse = voxel_grid(cloud, coarse);
  const PlaneFit floor = fit_plane_ransac(sparse, params.ransac);
  if (!floor.found) return cloud;
  return far_from_plane(cloud, floor, params.ransac.threshold);
}

model::PointCloud mark_negative_obstacles(const model::PointCloud& cloud,
                                          const model::NegativeObstacleParams& params) {
  model::PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  result.points.reserve(cloud.size() + cloud.size() / 8);
  const double ox = cloud.origin.x(), oy = cloud.origin.y(), oz = cloud.origin.z();
  std::vector<model::Point3f> virtual_points;
  for (const model::Point3f& p : cloud.points) {
    if (p.z() >= params.below) {
      result.points.push_back(p);
      continue;
    }
    result.points.emplace_back(p.x(), p.y(), -p.z());
    const double s = oz / (oz - p.z());  // where the ray O -> P crosses z = 0
    virtual_points.emplace_back(static_cast<float>(ox + (p.x() - ox) * s),
                                static_cast<float>(oy + (p.y() - oy) * s),
                                static_cast<float>(params.virtual_height));
  }
  result.points.insert(result.points.end(), virtual_points.begin(), virtual_points.end());
  return result;
}

}  // namespace rigdesign::filters
