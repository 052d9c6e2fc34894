#include "rigdesign/geometry/body_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

#include "rigdesign/model/polygon_area.hpp"

namespace rigdesign::geometry {
namespace {

// Sides of the prism that stands for a round part; 64 keeps it within 0.12 % of the radius.
constexpr int kCylinderSides = 64;

// Twice the signed area of triangle a-b-c: positive when it turns left (counter-clockwise).
double turn(const model::Vec2& a, const model::Vec2& b, const model::Vec2& c) {
  const model::Vec2 ab = b - a;
  const model::Vec2 ac = c - a;
  return ab.x() * ac.y() - ab.y() * ac.x();
}

// A point on the border counts as inside, so an ear never swallows a vertex touching it.
bool inside_or_on(const model::Vec2& p, const model::Vec2& a, const model::Vec2& b,
                  const model::Vec2& c) {
  return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

bool is_ear(const std::vector<model::Vec2>& polygon, const std::vector<int>& remaining,
            std::size_t k) {
  const std::size_t count = remaining.size();
  const int prev = remaining[(k + count - 1) % count];
  const int here = remaining[k];
  const int next = remaining[(k + 1) % count];
  if (turn(polygon[prev], polygon[here], polygon[next]) <= 0) return false;  // reflex or straight
  for (const int other : remaining) {
    if (other == prev || other == here || other == next) continue;
    if (inside_or_on(polygon[other], polygon[prev], polygon[here], polygon[next])) return false;
  }
  return true;
}

// When no ear is left, what remains is straight runs, where dropping the straightest vertex
// loses no area, or a self-intersecting outline, which has no proper triangulation; dropping
// its straightest vertex still ends the loop and draws something.
std::size_t straightest_corner(const std::vector<model::Vec2>& polygon,
                               const std::vector<int>& remaining) {
  const std::size_t count = remaining.size();
  std::size_t best = 0;
  double best_turn = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < count; ++k) {
    const double bend = std::abs(turn(polygon[remaining[(k + count - 1) % count]],
                                      polygon[remaining[k]], polygon[remaining[(k + 1) % count]]));
    if (bend < best_turn) {
      best_turn = bend;
      best = k;
    }
  }
  return best;
}

// Ear clipping of a simple counter-clockwise polygon (any convexity): repeatedly cut off a
// convex corner whose triangle holds no other vertex. Returns triangles of polygon indices.
std::vector<std::array<int, 3>> triangulate(const std::vector<model::Vec2>& polygon) {
  std::vector<int> remaining(polygon.size());
  std::iota(remaining.begin(), remaining.end(), 0);
  std::vector<std::array<int, 3>> triangles;
  while (remaining.size() >= 3) {
    const std::size_t count = remaining.size();
    std::size_t cut = count;
    for (std::size_t k = 0; k < count && cut == count; ++k) {
      if (is_ear(polygon, remaining, k)) cut = k;
    }
    if (cut == count) cut = straightest_corner(polygon, remaining);
    const int prev = remaining[(cut + count - 1) % count];
    const int here = remaining[cut];
    const int next = remaining[(cut + 1) % count];
    if (turn(polygon[prev], polygon[here], polygon[next]) > 0) {
      triangles.push_back({prev, here, next});
    }
    remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(cut));
  }
  return triangles;
}

std::vector<model::Vec2> circle_outline(const model::Vec2& centre, double radius) {
  std::vector<model::Vec2> circle;
  circle.reserve(kCylinderSides);
  for (int i = 0; i < kCylinderSides; ++i) {
    const double angle = 2 * std::numbers::pi * i / kCylinderSides;
    circle.push_back(centre + radius * model::Vec2(std::cos(angle), std::sin(angle)));
  }
  return circle;
}

std::vector<model::Vec2> counter_clockwise_outline(const model::RobotBody& body) {
  if (!body.footprint.empty()) {
    std::vector<model::Vec2> outline = body.footprint;
    if (model::signed_area(outline) < 0) std::reverse(outline.begin(), outline.end());
    return outline;
  }
  return circle_outline(model::Vec2::Zero(), body.radius);
}

// A vertical prism over a counter-clockwise `outline` from z_low to z_high, closed by its
// floor and top faces, wound outward.
model::TriangleMesh prism_mesh(const std::vector<model::Vec2>& outline, double z_low,
                               double z_high) {
  const int count = static_cast<int>(outline.size());
  model::TriangleMesh mesh;
  if (count < 3) return mesh;
  // Vertices 0..count-1 on the floor, count..2*count-1 on the top, in outline order.
  for (const double z : {z_low, z_high}) {
    for (const model::Vec2& corner : outline) mesh.vertices.emplace_back(corner.x(), corner.y(), z);
  }
  for (const auto& [a, b, c] : triangulate(outline)) {
    mesh.triangles.push_back({count + a, count + b, count + c});  // top faces up
    mesh.triangles.push_back({a, c, b});                          // floor faces down
  }
  for (int i = 0; i < count; ++i) {
    // Outward is to the right of a counter-clockwise edge; the quad runs floor, then top.
    const int next = (i + 1) % count;
    mesh.triangles.push_back({i, next, count + next});
    mesh.triangles.push_back({i, count + next, count + i});
  }
  return mesh;
}

// A description's collision parts as drawn: triangles as they are, vertical cylinders as
// prisms of kCylinderSides.
model::TriangleMesh parts_mesh(const std::vector<model::BodyPart>& parts) {
  model::TriangleMesh mesh;
  for (const model::BodyPart& part : parts) {
    if (!part.cylinder) {
      mesh.append(part.triangles);
      continue;
    }
    const model::VerticalCylinder& c = *part.cylinder;
    mesh.append(prism_mesh(circle_outline(c.centre, c.radius), c.z_min, c.z_max));
  }
  return mesh;
}

}  // namespace

model::TriangleMesh body_mesh(const model::RobotBody& body) {
  if (body.has_parts()) return parts_mesh(body.parts);
  return prism_mesh(counter_clockwise_outline(body), 0.0, body.height);
}

}  // namespace rigdesign::geometry
