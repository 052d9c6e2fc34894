#include "rigdesign/localize/geometry_analysis.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace rigdesign::localize {

model::Vec3 GeometryAnalysis::mirror(const model::Vec3& point) const {
  const model::Vec3 offset = point - centroid;
  model::Vec3 image = centroid + 2.0 * offset.dot(principal_axis) * principal_axis - offset;
  if (dimensions == 2) image.z() = point.z();
  return image;
}

model::Vec3 GeometryAnalysis::inverse(const model::Vec3& point) const {
  model::Vec3 offset = point - circle_centre;
  offset.z() = 0.0;
  const double squared = std::max(offset.squaredNorm(), 1e-12);
  model::Vec3 image = circle_centre + circle_radius * circle_radius / squared * offset;
  image.z() = point.z();
  return image;
}

namespace {

// Algebraic (Kasa) circle fit in x, y: x^2 + y^2 = 2 c . p + (r^2 - |c|^2) in least squares,
// count-weighted. Sets circular when the RMS radial residual is small against the radius.
void fit_circle(const std::vector<Chunk>& chunks, const GeometryParams& params,
                GeometryAnalysis* analysis) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const Chunk& chunk : chunks) {
    const model::Vec3 p = chunk.position() - analysis->centroid;  // centred for conditioning
    const Eigen::Vector3d row(2 * p.x(), 2 * p.y(), 1.0);
    normal += chunk.count * row * row.transpose();
    rhs += chunk.count * row * (p.x() * p.x() + p.y() * p.y());
  }
  const Eigen::Vector3d solution = normal.ldlt().solve(rhs);
  const double r2 = solution(2) + solution(0) * solution(0) + solution(1) * solution(1);
  if (!solution.allFinite() || !(r2 > 0)) return;
  analysis->circle_centre = analysis->centroid + model::Vec3(solution(0), solution(1), 0.0);
  analysis->circle_radius = std::sqrt(r2);
  double squares = 0.0, total = 0.0;
  for (const Chunk& chunk : chunks) {
    const double radial = std::hypot(chunk.position().x() - analysis->circle_centre.x(),
                                     chunk.position().y() - analysis->circle_centre.y()) -
                          analysis->circle_radius;
    squares += chunk.count * radial * radial;
    total += chunk.count;
  }
  analysis->circular =
      std::sqrt(squares / total) < params.max_circle_residual * analysis->circle_radius;
}

}  // namespace

GeometryAnalysis analyse_geometry(const std::vector<Chunk>& chunks, const GeometryParams& params) {
  GeometryAnalysis analysis;
  analysis.chunks = static_cast<int>(chunks.size());
  double total = 0.0;
  for (const Chunk& chunk : chunks) {
    analysis.centroid += chunk.count * chunk.position();
    total += chunk.count;
  }
  if (total <= 0) return analysis;
  analysis.centroid /= total;
  model::Mat3 scatter = model::Mat3::Zero();
  for (const Chunk& chunk : chunks) {
    const model::Vec3 offset = chunk.position() - analysis.centroid;
    scatter += chunk.count * offset * offset.transpose();
  }
  scatter /= total;
  analysis.height_spread = std::sqrt(std::max(0.0, scatter(2, 2)));
  analysis.dimensions = analysis.height_spread >= params.min_height_spread ? 3 : 2;
  const int d = analysis.dimensions;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scatter.topLeftCorner(d, d));
  // Eigen sorts eigenvalues in increasing order.
  const auto values = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  analysis.along_spread = values(d - 1);
  analysis.lateral_spread = values(d - 2);
  analysis.principal_axis = model::Vec3::Zero();
  for (int k = 0; k < d; ++k) analysis.principal_axis(k) = eigen.eigenvectors()(k, d - 1);
  analysis.collinear = analysis.lateral_spread < params.min_lateral_spread;
  if (!analysis.collinear && chunks.size() >= 3) fit_circle(chunks, params, &analysis);
  return analysis;
}

}  // namespace rigdesign::localize
