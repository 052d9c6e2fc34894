#pragma once
/// Where a line c + t w crosses a quadric or a plane: the roots that split a line into pieces
/// on which an inside test is constant (coverage along a line, shadows, filtered regions).
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// Real roots of a t^2 + b t + c = 0 (one root when a is negligible) appended to `roots`.
void append_quadratic_roots(double a, double b, double c, std::vector<double>& roots);
/// The root of n . (c + t w) = 0, unless the line runs parallel to the plane.
void append_plane_crossing(const Vec3& normal, const Vec3& c, const Vec3& w,
                           std::vector<double>& roots);
/// The roots where the angle between c + t w and the unit `axis` has cosine +-`cosine`:
/// (axis . q)^2 = cosine^2 |q|^2, the double cone about `axis`.
void append_cone_crossings(const Vec3& axis, double cosine, const Vec3& c, const Vec3& w,
                           std::vector<double>& roots);
/// The roots where |c + t w| = radius.
void append_sphere_crossings(const Vec3& c, const Vec3& w, double radius,
                             std::vector<double>& roots);

}  // namespace rigdesign::model
