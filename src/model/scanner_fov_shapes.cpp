// The scanner shapes: a spinning lidar's band of elevations over an azimuth span, and a 2D
// scanner's planar fan (a band one beam divergence thick). Their rays step evenly in angle.
#include <cmath>
#include <numbers>

#include "fov_shape_helpers.hpp"
#include "rigdesign/model/fov_shape.hpp"
#include "rigdesign/model/line_crossings.hpp"

namespace rigdesign::model {
namespace {

class BandFov : public FovShape {
 public:
  BandFov(double horizontal, double elevation_min, double elevation_max)
      : FovShape(horizontal, elevation_max - elevation_min, elevation_min, elevation_max),
        sin_elevation_min_(std::sin(elevation_min)),
        sin_elevation_max_(std::sin(elevation_max)),
        half_span_(horizontal / 2) {}

  std::string_view name() const override { return "band"; }
  bool is_camera() const override { return false; }
  bool is_planar_scan() const override { return false; }

  // u = azimuth atan2(y, x), v = elevation asin(z).
  AngularDomain domain() const override {
    const double half_span = std::min(half_span_, std::numbers::pi);
    AngularDomain range{-half_span, half_span, elevation_min(), elevation_max()};
    range.wraps_u = half_span >= std::numbers::pi - kFovAngleTolerance;
    range.pole_at_v_min = range.v_min <= -std::numbers::pi / 2 + kFovAngleTolerance;
    range.pole_at_v_max = range.v_max >= std::numbers::pi / 2 - kFovAngleTolerance;
    return range;
  }
  Vec3 direction(double u, double v) const override {
    return Vec3(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
  }
  bool contains(const Vec3& q) const override {
    const double distance = q.norm();
    if (q.z() < sin_elevation_min_ * distance || q.z() > sin_elevation_max_ * distance) {
      return false;
    }
    if (half_span_ >= std::numbers::pi) return true;
    return std::abs(std::atan2(q.y(), q.x())) <= half_span_;
  }
  void append_boundary_crossings(const Vec3& c, const Vec3& w,
                                 std::vector<double>& crossings) const override {
    // Elevation limits are cones about the sensor's z axis; their sign flips at q_z = 0.
    append_cone_crossings(Vec3::UnitZ(), sin_elevation_min_, c, w, crossings);
    append_cone_crossings(Vec3::UnitZ(), sin_elevation_max_, c, w, crossings);
    append_plane_crossing(Vec3::UnitZ(), c, w, crossings);
    if (half_span_ < std::numbers::pi) {  // azimuth limits: half-planes through the z axis
      append_plane_crossing(Vec3(-std::sin(half_span_), std::cos(half_span_), 0), c, w, crossings);
      append_plane_crossing(Vec3(std::sin(half_span_), std::cos(half_span_), 0), c, w, crossings);
      append_plane_crossing(Vec3::UnitX(), c, w, crossings);
      append_plane_crossing(Vec3::UnitY(), c, w, crossings);
    }
  }
  // Above the upper elevation cone (convex when its limit is >= 0), or below the lower one.
  bool excludes_triangle(const std::array<Vec3, 3>& q) const override {
    const auto all_below = [&](const Vec3& normal, double sin_limit) {
      for (const Vec3& p : q) {
        if (!(normal.dot(p) < sin_limit * p.norm())) return false;
      }
      return true;
    };
    return (sin_elevation_max_ >= 0 && all_below(-Vec3::UnitZ(), -sin_elevation_max_)) ||
           (sin_elevation_min_ <= 0 && all_below(Vec3::UnitZ(), sin_elevation_min_));
  }
  // A band reaches round the sensor: assume some ray points back.
  bool may_point_against(const Mat3&, const Vec3&) const override { return true; }
  std::optional<std::array<Vec3, 4>> bounding_corners() const override { return std::nullopt; }
  std::vector<Vec3> ray_pattern(double step_h, double step_v) const override {
    return scan_rows(step_h, angle_steps(vertical(), step_v) + 1);
  }
  std::vector<NamedAngle> report_angles() const override {
    return {{"horizontal_deg", horizontal()},
            {"elevation_min_deg", elevation_min()},
            {"elevation_max_deg", elevation_max()}};
  }
  std::string summary_deg() const override {
    return degrees_text(horizontal()) + " (" + degrees_text(elevation_min()) + ".." +
           degrees_text(elevation_max()) + ")";
  }

 protected:
  // Rows from the lowest elevation up (one row: the middle elevation), each sweeping the
  // azimuths from -span/2; a full turn has as many columns as steps, a sector both edges.
  std::vector<Vec3> scan_rows(double step_h, int rows) const {
    std::vector<Vec3> rays;
    const bool full_circle = horizontal() >= 2 * std::numbers::pi - kFovAngleTolerance;
    const int columns = angle_steps(horizontal(), step_h) + (full_circle ? 0 : 1);
    for (int row = 0; row < rows; ++row) {
      const double elevation = rows == 1 ? 0.5 * (elevation_min() + elevation_max())
                                         : elevation_min() + vertical() * row / (rows - 1);
      for (int column = 0; column < columns; ++column) {
        const double azimuth = full_circle
                                   ? 2 * std::numbers::pi * column / columns - std::numbers::pi
                                   : -horizontal() / 2 + horizontal() * column / (columns - 1);
        rays.emplace_back(std::cos(elevation) * std::cos(azimuth),
                          std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      }
    }
    return rays;
  }

 private:
  double sin_elevation_min_;
  double sin_elevation_max_;
  double half_span_;
};

class PlanarFov final : public BandFov {
 public:
  PlanarFov(double horizontal, double divergence)
      : BandFov(horizontal, -divergence / 2, divergence / 2) {}

  std::string_view name() const override { return "planar"; }
  bool is_planar_scan() const override { return true; }
  std::vector<Vec3> ray_pattern(double step_h, double) const override {
    return scan_rows(step_h, 1);
  }
  std::vector<NamedAngle> report_angles() const override {
    return {{"horizontal_deg", horizontal()}, {"vertical_deg", vertical()}};
  }
  std::string summary_deg() const override { return degrees_text(horizontal()) + " planar"; }
};

}  // namespace

std::shared_ptr<const FovShape> band_fov(double horizontal, double elevation_min,
                                         double elevation_max) {
  return std::make_shared<const BandFov>(horizontal, elevation_min, elevation_max);
}

std::shared_ptr<const FovShape> planar_fov(double horizontal, double divergence) {
  return std::make_shared<const PlanarFov>(horizontal, divergence);
}

}  // namespace rigdesign::model
