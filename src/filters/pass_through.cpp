#include "rigdesign/filters/pass_through.hpp"

namespace rigdesign::filters {

std::vector<std::uint32_t> pass_through_indices(const model::PointCloud& cloud,
                                                const model::PassThroughParams& params) {
  std::vector<std::uint32_t> kept;
  kept.reserve(cloud.size());
  const float low = static_cast<float>(params.min);
  const float high = static_cast<float>(params.max);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const float value = cloud.points[i][params.axis];
    const bool inside = value >= low && value <= high;
    if (inside != params.negative) kept.push_back(static_cast<std::uint32_t>(i));
  }
  return kept;
}

model::PointCloud pass_through(const model::PointCloud& cloud,
                               const model::PassThroughParams& params) {
  model::PointCloud result;
  result.origin = cloud.origin;
  result.orientation = cloud.orientation;
  const float low = static_cast<float>(params.min);
  const float high = static_cast<float>(params.max);
  result.points.reserve(cloud.size());
  for (const model::Point3f& p : cloud.points) {
    const bool inside = p[params.axis] >= low && p[params.axis] <= high;
    if (inside != params.negative) result.points.push_back(p);
  }
  return result;
}

}  // namespace rigdesign::filters
