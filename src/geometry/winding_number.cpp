#include "rigdesign/geometry/winding_number.hpp"

#include <cmath>
#include <numbers>

namespace rigdesign::geometry {
namespace {

// Signed solid angle of triangle abc seen from the origin: tan(omega / 2) =
// a.(b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|), with atan2 for the full range.
double solid_angle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2.0 * std::atan2(numerator, denominator);
}

}  // namespace

double winding_number(const model::TriangleMesh& mesh, const model::Vec3& point) {
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    total += solid_angle(mesh.vertices[t[0]] - point, mesh.vertices[t[1]] - point,
                         mesh.vertices[t[2]] - point);
  }
  return total / (4.0 * std::numbers::pi);
}

bool inside_mesh(const model::TriangleMesh& mesh, const model::Vec3& point) {
  return std::abs(winding_number(mesh, point)) >= 0.5;
}

bool inside_part(const model::BodyPart& part, const model::Vec3& point) {
  if (part.cylinder) {
    const model::VerticalCylinder& c = *part.cylinder;
    return (point.head<2>() - c.centre).norm() < c.radius && point.z() > c.z_min &&
           point.z() < c.z_max;
  }
  return inside_mesh(part.triangles, point);
}

}  // namespace rigdesign::geometry
