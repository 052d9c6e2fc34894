#include "rigdesign/sim/mesh_primitives.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigdesign::sim {
namespace {

bool inside(const Rect2& rect, const model::Vec2& point) {
  return point.x() > rect.low.x() && point.x() < rect.high.x() && point.y() > rect.low.y() &&
         point.y() < rect.high.y();
}

// Sorted, deduplicated cut positions along one axis, clipped to [low, high].
std::vector<double> cuts(double low, double high, const std::vector<double>& candidates) {
  std::vector<double> result{low, high};
  for (double cut : candidates) {
    if (cut > low && cut < high) result.push_back(cut);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

}  // namespace

model::TriangleMesh box_mesh(const model::Vec3& size, const model::Pose3& T_world_box) {
  model::TriangleMesh mesh;
  // Corner i has bit 0 set for +x, bit 1 for +y, bit 2 for +z.
  for (int corner = 0; corner < 8; ++corner) {
    const model::Vec3 sign((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5,
                           (corner & 4) ? 0.5 : -0.5);
    mesh.vertices.push_back(T_world_box * model::Vec3(sign.cwiseProduct(size)));
  }
  // Two triangles per face, each counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 3}, {0, 3, 1},   // -z
                    {4, 5, 7}, {4, 7, 6},   // +z
                    {0, 1, 5}, {0, 5, 4},   // -y
                    {2, 6, 7}, {2, 7, 3},   // +y
                    {0, 4, 6}, {0, 6, 2},   // -x
                    {1, 3, 7}, {1, 7, 5}};  // +x
  return mesh;
}

model::TriangleMesh aligned_box(const model::Vec3& low, const model::Vec3& high) {
  model::Pose3 T_world_box = model::Pose3::Identity();
  T_world_box.translation() = (low + high) / 2;
  return box_mesh(high - low, T_world_box);
}

model::TriangleMesh cylinder_mesh(double radius, double height,
                                  const model::Pose3& T_world_cylinder) {
  model::TriangleMesh mesh;
  const int n = kCylinderSegments;
  // Bottom ring is 0 .. n-1, top ring n .. 2n-1, both counter-clockwise seen from +z.
  for (int ring = 0; ring < 2; ++ring) {
    for (int i = 0; i < n; ++i) {
      const double angle = 2 * std::numbers::pi * i / n;
      mesh.vertices.push_back(T_world_cylinder * model::Vec3(radius * std::cos(angle),
                                                             radius * std::sin(angle),
                                                             ring * height));
    }
  }
  for (int i = 0; i < n; ++i) {
    const int next = (i + 1) % n;
    mesh.triangles.push_back({i, next, n + next});
    mesh.triangles.push_back({i, n + next, n + i});
  }
  // Caps as fans from their first vertex; the bottom one reversed so it faces -z.
  for (int i = 1; i + 1 < n; ++i) {
    mesh.triangles.push_back({n, n + i, n + i + 1});
    mesh.triangles.push_back({0, i + 1, i});
  }
  return mesh;
}

model::TriangleMesh cylinder_between(const model::Vec3& start, const model::Vec3& end,
                                     double radius) {
  const model::Vec3 axis = end - start;
  model::Pose3 T_world_cylinder = model::Pose3::Identity();
  T_world_cylinder.linear() =
      Eigen::Quaterniond::FromTwoVectors(model::Vec3::UnitZ(), axis).toRotationMatrix();
  T_world_cylinder.translation() = start;
  return cylinder_mesh(radius, axis.norm(), T_world_cylinder);
}

model::TriangleMesh floor_rectangle(const Rect2& area, double z) {
  model::TriangleMesh mesh;
  mesh.vertices = {{area.low.x(), area.low.y(), z},
                   {area.high.x(), area.low.y(), z},
                   {area.high.x(), area.high.y(), z},
                   {area.low.x(), area.high.y(), z}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

model::TriangleMesh floor_with_openings(const Rect2& area, const std::vector<Rect2>& openings,
                                        double z) {
  std::vector<double> x_candidates;
  std::vector<double> y_candidates;
  for (const Rect2& opening : openings) {
    x_candidates.insert(x_candidates.end(), {opening.low.x(), opening.high.x()});
    y_candidates.insert(y_candidates.end(), {opening.low.y(), opening.high.y()});
  }
  const std::vector<double> xs = cuts(area.low.x(), area.high.x(), x_candidates);
  const std::vector<double> ys = cuts(area.low.y(), area.high.y(), y_candidates);
  model::TriangleMesh mesh;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      const Rect2 cell{{xs[i], ys[j]}, {xs[i + 1], ys[j + 1]}};
      // Every cell lies wholly inside or wholly outside each opening, so its centre decides.
      const model::Vec2 centre = (cell.low + cell.high) / 2;
      const bool open = std::any_of(openings.begin(), openings.end(),
                                    [&](const Rect2& opening) { return inside(opening, centre); });
      if (!open) mesh.append(floor_rectangle(cell, z));
    }
  }
  return mesh;
}

}  // namespace rigdesign::sim
