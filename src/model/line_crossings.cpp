#include "rigdesign/model/line_crossings.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::model {

void append_quadratic_roots(double a, double b, double c, std::vector<double>& roots) {
  const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
  if (scale == 0.0) return;
  if (std::abs(a) <= 1e-14 * scale) {
    if (std::abs(b) > 1e-14 * scale) roots.push_back(-c / b);
    return;
  }
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return;
  // Citardauq form avoids cancellation when b^2 >> 4ac.
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  if (q != 0.0) {
    roots.push_back(q / a);
    roots.push_back(c / q);
  } else {
    roots.push_back(0.0);
  }
}

void append_plane_crossing(const Vec3& normal, const Vec3& c, const Vec3& w,
                           std::vector<double>& roots) {
  const double slope = normal.dot(w);
  if (std::abs(slope) > 1e-15) roots.push_back(-normal.dot(c) / slope);
}

void append_cone_crossings(const Vec3& axis, double cosine, const Vec3& c, const Vec3& w,
                           std::vector<double>& roots) {
  const double kc = axis.dot(c);
  const double kw = axis.dot(w);
  const double s2 = cosine * cosine;
  append_quadratic_roots(kw * kw - s2 * w.squaredNorm(), 2 * (kc * kw - s2 * c.dot(w)),
                         kc * kc - s2 * c.squaredNorm(), roots);
}

void append_sphere_crossings(const Vec3& c, const Vec3& w, double radius,
                             std::vector<double>& roots) {
  append_quadratic_roots(w.squaredNorm(), 2 * c.dot(w), c.squaredNorm() - radius * radius, roots);
}

}  // namespace rigdesign::model
