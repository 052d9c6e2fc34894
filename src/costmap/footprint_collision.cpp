#include "rigdesign/costmap/footprint_collision.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::costmap {
namespace {

// Sutherland-Hodgman against one horizontal plane: keeps the part with sign * (z - level) >= 0.
std::vector<model::Vec3> clip_by_height(const std::vector<model::Vec3>& polygon, double level,
                                        double sign) {
  std::vector<model::Vec3> kept;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const model::Vec3& a = polygon[i];
    const model::Vec3& b = polygon[(i + 1) % n];
    const double da = sign * (a.z() - level);
    const double db = sign * (b.z() - level);
    if (da >= 0) kept.push_back(a);
    if ((da >= 0) != (db >= 0)) kept.push_back(a + (b - a) * (da / (da - db)));
  }
  return kept;
}

double distance_to_segment(const model::Vec2& p, const model::Vec2& a, const model::Vec2& b) {
  const model::Vec2 ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double t =
      length_squared > 0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double cross(const model::Vec2& a, const model::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

double distance_to_convex_polygon(const model::Vec2& p, const std::vector<model::Vec2>& polygon) {
  if (polygon.empty()) return std::numeric_limits<double>::infinity();
  if (polygon.size() == 1) return (p - polygon.front()).norm();
  const std::size_t n = polygon.size();
  double area2 = 0.0;  // twice the signed area: zero for a projected vertical triangle
  bool all_left = true;
  bool all_right = true;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const model::Vec2& a = polygon[i];
    const model::Vec2& b = polygon[(i + 1) % n];
    area2 += cross(a, b);
    const double side = cross(b - a, p - a);
    all_left = all_left && side >= 0;
    all_right = all_right && side <= 0;
    nearest = std::min(nearest, distance_to_segment(p, a, b));
  }
  const bool has_interior = std::abs(area2) > 1e-12;
  return has_interior && (all_left || all_right) ? 0.0 : nearest;
}

FootprintCollisionChecker::FootprintCollisionChecker(const std::vector<NamedMesh>& meshes,
                                                     const HeightBand& band) {
  for (const NamedMesh& named : meshes) {
    const int object = static_cast<int>(names_.size());
    names_.push_back(named.name);
    const model::TriangleMesh& mesh = *named.mesh;
    for (const auto& triangle : mesh.triangles) {
      std::vector<model::Vec3> polygon = {mesh.vertices[static_cast<std::size_t>(triangle[0])],
                                          mesh.vertices[static_cast<std::size_t>(triangle[1])],
                                          mesh.vertices[static_cast<std::size_t>(triangle[2])]};
      polygon = clip_by_height(clip_by_height(polygon, band.bottom, 1.0), band.top, -1.0);
      if (polygon.empty()) continue;
      Piece piece;
      piece.object = object;
      for (const model::Vec3& v : polygon) {
        piece.polygon.push_back(v.head<2>());
        piece.bounds.extend(v.head<2>());
      }
      pieces_.push_back(std::move(piece));
    }
  }
}

Clearance FootprintCollisionChecker::clearance(const model::Vec2& centre_world,
                                               double radius) const {
  Clearance best;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Piece& piece : pieces_) {
    // The box distance is a lower bound: skip pieces that cannot beat the nearest so far.
    if (piece.bounds.exteriorDistance(centre_world) >= nearest) continue;
    const double d = distance_to_convex_polygon(centre_world, piece.polygon);
    if (d < nearest) {
      nearest = d;
      best.object = names_[static_cast<std::size_t>(piece.object)];
    }
  }
  if (std::isfinite(nearest)) best.distance = nearest - radius;
  return best;
}

std::vector<std::vector<model::Vec2>> FootprintCollisionChecker::outlines() const {
  std::vector<std::vector<model::Vec2>> outlines;
  outlines.reserve(pieces_.size());
  for (const Piece& piece : pieces_) outlines.push_back(piece.polygon);
  return outlines;
}

}  // namespace rigdesign::costmap
