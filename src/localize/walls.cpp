#include "rigdesign/localize/walls.hpp"

#include <cmath>

namespace rigdesign::localize {
namespace {

bool segments_cross(const model::Vec2& p, const model::Vec2& p2, const model::Vec2& q,
                    const model::Vec2& q2) {
  const auto cross = [](const model::Vec2& a, const model::Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  const model::Vec2 r = p2 - p, s = q2 - q;
  const double denominator = cross(r, s);
  if (std::abs(denominator) < 1e-12) return false;  // parallel: grazing a wall costs nothing
  const double t = cross(q - p, s) / denominator;
  const double u = cross(q - p, r) / denominator;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

}  // namespace

double wall_loss_db(const std::vector<WallSegment>& walls, const model::Vec2& from,
                    const model::Vec2& to) {
  double loss = 0.0;
  for (const WallSegment& wall : walls) {
    if (segments_cross(from, to, wall.a, wall.b)) loss += wall.attenuation_db;
  }
  return loss;
}

double wall_loss_db(const std::vector<WallSegment>& walls, const model::Vec3& from,
                    const model::Vec3& to) {
  return wall_loss_db(walls, model::Vec2(from.head<2>()), model::Vec2(to.head<2>()));
}

}  // namespace rigdesign::localize
