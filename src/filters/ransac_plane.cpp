#include "rigdesign/filters/ransac_plane.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

namespace rigdesign::filters {
namespace {

// Points copied into separate x, y, z arrays so the inlier count vectorises.
struct Columns {
  std::vector<float> x, y, z;
  std::vector<std::uint32_t> index;
};

Columns gather(const model::PointCloud& cloud, const std::vector<std::uint32_t>* subset) {
  Columns columns;
  const std::size_t n = subset ? subset->size() : cloud.size();
  columns.x.resize(n);
  columns.y.resize(n);
  columns.z.resize(n);
  columns.index.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t source = subset ? (*subset)[i] : static_cast<std::uint32_t>(i);
    const model::Point3f& p = cloud.points[source];
    columns.x[i] = p.x();
    columns.y[i] = p.y();
    columns.z[i] = p.z();
    columns.index[i] = source;
  }
  return columns;
}

std::size_t count_inliers(const Columns& c, const Eigen::Vector4f& plane, float threshold) {
  std::size_t count = 0;
  const std::size_t n = c.x.size();
  for (std::size_t i = 0; i < n; ++i) {
    const float distance = plane[0] * c.x[i] + plane[1] * c.y[i] + plane[2] * c.z[i] + plane[3];
    count += std::abs(distance) <= threshold ? 1 : 0;
  }
  return count;
}

// Least-squares plane through points: the centroid and the covariance's smallest eigenvector.
bool refine(const model::PointCloud& cloud, const std::vector<std::uint32_t>& inliers,
            PlaneFit& fit) {
  if (inliers.size() < 3) return false;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const std::uint32_t i : inliers) centroid += cloud.points[i].cast<double>();
  centroid /= static_cast<double>(inliers.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const std::uint32_t i : inliers) {
    const Eigen::Vector3d d = cloud.points[i].cast<double>() - centroid;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Vector3d normal = solver.eigenvectors().col(0);
  if (normal.z() < 0) normal = -normal;
  fit.normal = normal;
  fit.offset = -normal.dot(centroid);
  return true;
}

// RANSAC's stopping rule: after k samples of 3, an all-inlier sample was missed with
// probability (1 - w^3)^k; k is the smallest count that makes it 1 - confidence.
double hypotheses_needed(double inlier_share, const model::RansacPlaneParams& params) {
  const double all_inliers = inlier_share * inlier_share * inlier_share;
  if (params.confidence >= 1.0 || all_inliers <= 0.0) return static_cast<double>(params.iterations);
  if (all_inliers >= 1.0) return 1.0;
  return std::log(1.0 - params.confidence) / std::log(1.0 - all_inliers);
}

}  // namespace

std::vector<std::uint32_t> points_near_plane(const model::PointCloud& cloud, const PlaneFit& plane,
                                             double threshold) {
  std::vector<std::uint32_t> near;
  const Eigen::Vector3f normal = plane.normal.cast<float>();
  const float offset = static_cast<float>(plane.offset);
  const float limit = static_cast<float>(threshold);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (std::abs(normal.dot(cloud.points[i]) + offset) <= limit)
      near.push_back(static_cast<std::uint32_t>(i));
  }
  return near;
}

PlaneFit fit_plane_ransac(const model::PointCloud& cloud, const model::RansacPlaneParams& params,
                          const std::vector<std::uint32_t>* subset) {
  PlaneFit fit;
  const Columns columns = gather(cloud, subset);
  const std::size_t n = columns.x.size();
  if (n < 3) return fit;
  std::mt19937_64 rng(params.seed);
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  const float threshold = static_cast<float>(params.threshold);
  const double min_cos_tilt = params.max_tilt ? std::cos(*params.max_tilt) : -1.0;
  std::size_t best_count = 0;
  Eigen::Vector4f best_plane = Eigen::Vector4f::Zero();
  double needed = static_cast<double>(params.iterations);
  for (int iteration = 0; iteration < params.iterations && iteration < needed; ++iteration) {
    fit.hypotheses = iteration + 1;
    const std::size_t a = pick(rng), b = pick(rng), c = pick(rng);
    const Eigen::Vector3f pa(columns.x[a], columns.y[a], columns.z[a]);
    const Eigen::Vector3f pb(columns.x[b], columns.y[b], columns.z[b]);
    const Eigen::Vector3f pc(columns.x[c], columns.y[c], columns.z[c]);
    Eigen::Vector3f normal = (pb - pa).cross(pc - pa);
    const float length = normal.norm();
    if (length < 1e-12f) continue;  // collinear or repeated sample
    normal /= length;
    if (std::abs(normal.z()) < min_cos_tilt) continue;
    const Eigen::Vector4f plane(normal.x(), normal.y(), normal.z(), -normal.dot(pa));
    const std::size_t count = count_inliers(columns, plane, threshold);
    if (count > best_count) {
      best_count = count;
      best_plane = plane;
      needed = hypotheses_needed(static_cast<double>(count) / static_cast<double>(n), params);
    }
  }
  if (best_count < 3) return fit;
  fit.found = true;
  fit.normal = best_plane.head<3>().cast<double>();
  fit.offset = best_plane[3];
  if (fit.normal.z() < 0) {
    fit.normal = -fit.normal;
    fit.offset = -fit.offset;
  }
  std::vector<std::uint32_t> inliers;
  for (std::size_t i = 0; i < n; ++i) {
    const double distance = fit.normal.x() * columns.x[i] + fit.normal.y() * columns.y[i] +
                            fit.normal.z() * columns.z[i] + fit.offset;
    if (std::abs(distance) <= params.threshold) inliers.push_back(columns.index[i]);
  }
  refine(cloud, inliers, fit);
  fit.inliers.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const double distance = fit.normal.x() * columns.x[i] + fit.normal.y() * columns.y[i] +
                            fit.normal.z() * columns.z[i] + fit.offset;
    if (std::abs(distance) <= params.threshold) fit.inliers.push_back(columns.index[i]);
  }
  return fit;
}

}  // namespace rigdesign::filters
