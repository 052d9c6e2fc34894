#include "rigdesign/sim/mean_pooling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rigdesign::sim {

model::PointCloud mean_pool(const model::PointCloud& organised, int columns, int k) {
  if (columns < 1 || k < 1) throw std::invalid_argument("mean_pool: columns and k must be >= 1");
  const auto width = static_cast<std::size_t>(columns);
  if (organised.points.size() % width != 0)
    throw std::invalid_argument("mean_pool: the cloud is not a whole number of rows");
  const int rows = static_cast<int>(organised.points.size() / width);
  model::PointCloud pooled;
  pooled.origin = organised.origin;
  pooled.orientation = organised.orientation;
  for (int row = 0; row < rows; row += k) {
    for (int column = 0; column < columns; column += k) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int count = 0;
      for (int r = row; r < std::min(rows, row + k); ++r) {
        for (int c = column; c < std::min(columns, column + k); ++c) {
          const model::Point3f& p =
              organised.points[static_cast<std::size_t>(r) * width + static_cast<std::size_t>(c)];
          if (!p.allFinite()) continue;
          sum += p.cast<double>();
          ++count;
        }
      }
      if (count > 0) pooled.points.push_back((sum / count).cast<float>());
    }
  }
  return pooled;
}

int pattern_columns(const std::vector<model::Vec3>& rays) {
  // A row shares its image-plane height z / x (the rays are normalised, so z alone varies).
  int columns = 0;
  for (const model::Vec3& ray : rays) {
    if (std::abs(ray.z() / ray.x() - rays.front().z() / rays.front().x()) > 1e-9) break;
    ++columns;
  }
  return columns;
}

int pixel_grid_columns(const std::vector<model::Vec3>& rays) {
  const int columns = pattern_columns(rays);
  return columns > 0 && rays.size() % static_cast<std::size_t>(columns) == 0 ? columns : 0;
}

}  // namespace rigdesign::sim
