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
  // The runs between removed points copied whole: a floor is a few thousand points of a cloud
  // of tens of thousands, so most of the cloud goes in a few long copies.
  std::size_t from = 0;
  for (const std::uint32_t i : removed) {
    if (i < from) continue;  // a repeated index
    result.points.insert(result.points.end(),
                         cloud.points.begin() + static_cast<std::ptrdiff_t>(from),
                         cloud.points.begin() + static_cast<std::ptrdiff_t>(i));
    from = i + std::size_t{1};
  }
  result.points.insert(result.points.end(),
                       cloud.points.begin() + static_cast<std::ptrdiff_t>(from),
                       cloud.points.end());
  return result;
}

// The slice's points within `threshold` of the plane, in cloud order (the distance in float,
// as PCL's floor removal and the previous one-pass cut computed it).
std::vector<std::uint32_t> slice_near_plane(const model::PointCloud& cloud,
                                            const std::vector<std::uint32_t>& slice,
                                            const PlaneFit& plane, double threshold) {
  const Eigen::Vector3f normal = plane.normal.cast<float>();
  const float offset = static_cast<float>(plane.offset);
  const float limit = static_cast<float>(threshold);
  std::vector<std::uint32_t> near;
  near.reserve(slice.size());
  for (const std::uint32_t i : slice) {
    if (std::abs(normal.dot(cloud.points[i]) + offset) <= limit) near.push_back(i);
  }
  return near;
}

}  // namespace

model::PointCloud remove_floor_1(const model::PointCloud& cloud,
                                 const model::FloorRemoval1Params& params) {
  const std::vector<std::uint32_t> slice = pass_through_indices(cloud, params.slice);
  const PlaneFit floor = fit_plane_ransac(cloud, params.ransac, &slice);
  if (!floor.found) return cloud;
  return without(cloud, floor.inliers);
}

// Paper 1, section 3: floor removal 1 "enhanced": the plane is searched on a coarse copy of
// the slice (a few hundred voxel centroids instead of the slice's thousands of points).
model::PointCloud remove_floor_2(const model::PointCloud& cloud,
                                 const model::FloorRemoval2Params& params) {
  const std::vector<std::uint32_t> slice = pass_through_indices(cloud, params.slice);
  model::VoxelGridParams coarse;
  coarse.leaf = params.coarse_leaf;
  const model::PointCloud sparse = voxel_grid(select_points(cloud, slice), coarse);
  const PlaneFit floor = fit_plane_ransac(sparse, params.ransac);
  if (!floor.found) return cloud;
  return without(cloud, slice_near_plane(cloud, slice, floor, params.ransac.threshold));
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
