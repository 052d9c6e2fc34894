// The camera shapes: a frustum (pyramid) and a circular cone about the optical axis x. Their
// rays are pixels on the image plane x = 1, not steps in angle.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fov_shape_helpers.hpp"
#include "rigdesign/model/fov_shape.hpp"
#include "rigdesign/model/line_crossings.hpp"

namespace rigdesign::model {
namespace {

// Pixel centres of a pinhole camera: evenly spaced on the image plane x = 1, top row first and
// left column first, as an image is stored; `circular` keeps those inside the inscribed circle.
std::vector<Vec3> pinhole_grid(double horizontal, double vertical, double step_h, double step_v,
                               bool circular) {
  const int columns = angle_steps(horizontal, step_h);
  const int rows = angle_steps(vertical, step_v);
  std::vector<Vec3> rays;
  const double half_width = std::tan(horizontal / 2);
  const double half_height = std::tan(vertical / 2);
  rays.reserve(static_cast<std::size_t>(columns) * rows);
  for (int row = 0; row < rows; ++row) {
    const double z = half_height * (1 - 2 * (row + 0.5) / rows);
    for (int column = 0; column < columns; ++column) {
      const double y = half_width * (1 - 2 * (column + 0.5) / columns);
      if (circular && y * y + z * z > half_width * half_width) continue;
      rays.push_back(Vec3(1.0, y, z).normalized());
    }
  }
  return rays;
}

// A triangle is outside a camera's FOV when one face plane of the frustum (or of the square
// frustum around a cone) has all three corners on its outer side.
bool outside_frustum(const std::array<Vec3, 3>& q, double tan_h, double tan_v) {
  const Vec3 planes[5] = {{1, 0, 0}, {tan_h, -1, 0}, {tan_h, 1, 0}, {tan_v, 0, -1}, {tan_v, 0, 1}};
  for (const Vec3& n : planes) {
    if (std::all_of(q.begin(), q.end(), [&](const Vec3& p) { return n.dot(p) < 0.0; })) {
      return true;
    }
  }
  return false;
}

std::array<Vec3, 4> frustum_corners(double tan_h, double tan_v) {
  std::array<Vec3, 4> corners;
  int k = 0;
  for (const double sy : {-1.0, 1.0}) {
    for (const double sz : {-1.0, 1.0}) corners[k++] = Vec3(1.0, sy * tan_h, sz * tan_v);
  }
  return corners;
}

// What both camera shapes answer alike: rays on an image grid, reported by their two angles.
class CameraFov : public FovShape {
 public:
  using FovShape::FovShape;
  bool is_camera() const override { return true; }
  bool is_planar_scan() const override { return false; }
  std::vector<NamedAngle> report_angles() const override {
    return {{"horizontal_deg", horizontal()}, {"vertical_deg", vertical()}};
  }
};

class PyramidFov final : public CameraFov {
 public:
  PyramidFov(double horizontal, double vertical)
      : CameraFov(horizontal, vertical, -vertical / 2, vertical / 2),
        tan_half_h_(std::tan(horizontal / 2)),
        tan_half_v_(std::tan(vertical / 2)) {}

  std::string_view name() const override { return "pyramid"; }

  // u = atan(y/x), v = atan(z/x).
  AngularDomain domain() const override {
    return {-horizontal() / 2, horizontal() / 2, -vertical() / 2, vertical() / 2};
  }
  Vec3 direction(double u, double v) const override {
    return Vec3(1.0, std::tan(u), std::tan(v)).normalized();
  }
  bool contains(const Vec3& q) const override {
    return q.x() > 0 && std::abs(q.y()) <= tan_half_h_ * q.x() &&
           std::abs(q.z()) <= tan_half_v_ * q.x();
  }
  void append_boundary_crossings(const Vec3& c, const Vec3& w,
                                 std::vector<double>& crossings) const override {
    append_plane_crossing(Vec3(1, 0, 0), c, w, crossings);
    for (const double sign : {-1.0, 1.0}) {
      append_plane_crossing(Vec3(tan_half_h_, sign, 0), c, w, crossings);
      append_plane_crossing(Vec3(tan_half_v_, 0, sign), c, w, crossings);
    }
  }
  bool excludes_triangle(const std::array<Vec3, 3>& q) const override {
    return outside_frustum(q, tan_half_h_, tan_half_v_);
  }
  // Directions of a pyramid are positive combinations of its four corner rays.
  bool may_point_against(const Mat3& R_robot_sensor, const Vec3& outward) const override {
    for (const Vec3& corner : frustum_corners(tan_half_h_, tan_half_v_)) {
      if ((R_robot_sensor * corner).dot(outward) < 0) return true;
    }
    return false;
  }
  std::optional<std::array<Vec3, 4>> bounding_corners() const override {
    return frustum_corners(tan_half_h_, tan_half_v_);
  }
  std::vector<Vec3> ray_pattern(double step_h, double step_v) const override {
    return pinhole_grid(horizontal(), vertical(), step_h, step_v, false);
  }
  std::string summary_deg() const override {
    return degrees_text(horizontal()) + " x " + degrees_text(vertical());
  }

 private:
  double tan_half_h_;
  double tan_half_v_;
};

class ConeFov final : public CameraFov {
 public:
  explicit ConeFov(double apex)
      : CameraFov(apex, apex, -apex / 2, apex / 2),
        tan_half_apex_(std::tan(apex / 2)),
        cos_half_apex_(std::cos(apex / 2)) {}

  std::string_view name() const override { return "cone"; }

  // u = roll about x, v = angle from +x; the axis is a pole.
  AngularDomain domain() const override {
    AngularDomain range{-std::numbers::pi, std::numbers::pi, 0.0,
                        std::min(horizontal() / 2, std::numbers::pi)};
    range.wraps_u = true;
    range.pole_at_v_min = true;
    range.pole_at_v_max = range.v_max >= std::numbers::pi - kFovAngleTolerance;
    return range;
  }
  Vec3 direction(double u, double v) const override {
    return Vec3(std::cos(v), std::sin(v) * std::sin(u), std::sin(v) * std::cos(u));
  }
  bool contains(const Vec3& q) const override { return q.x() >= cos_half_apex_ * q.norm(); }
  void append_boundary_crossings(const Vec3& c, const Vec3& w,
                                 std::vector<double>& crossings) const override {
    append_cone_crossings(Vec3::UnitX(), cos_half_apex_, c, w, crossings);
    append_plane_crossing(Vec3::UnitX(), c, w, crossings);
  }
  // The cone lies inside its square frustum.
  bool excludes_triangle(const std::array<Vec3, 3>& q) const override {
    return outside_frustum(q, tan_half_apex_, tan_half_apex_);
  }
  // A cone's directions stay within its half-angle of the axis.
  bool may_point_against(const Mat3& R_robot_sensor, const Vec3& outward) const override {
    const double axis_to_outward = std::acos(
        std::clamp((R_robot_sensor * Vec3::UnitX()).dot(outward.normalized()), -1.0, 1.0));
    return axis_to_outward + horizontal() / 2 > std::numbers::pi / 2;
  }
  std::optional<std::array<Vec3, 4>> bounding_corners() const override {
    return frustum_corners(tan_half_apex_, tan_half_apex_);
  }
  std::vector<Vec3> ray_pattern(double step_h, double step_v) const override {
    return pinhole_grid(horizontal(), horizontal(), step_h, step_v, true);
  }
  std::string summary_deg() const override { return "cone " + degrees_text(horizontal()); }

 private:
  double tan_half_apex_;
  double cos_half_apex_;
};

}  // namespace

std::shared_ptr<const FovShape> pyramid_fov(double horizontal, double vertical) {
  return std::make_shared<const PyramidFov>(horizontal, vertical);
}

std::shared_ptr<const FovShape> cone_fov(double apex) {
  return std::make_shared<const ConeFov>(apex);
}

}  // namespace rigdesign::model
