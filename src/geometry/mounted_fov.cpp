#include "rigdesign/geometry/mounted_fov.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/model/units.hpp"

namespace rigdesign::geometry {
namespace {

// Pieces of a line shorter than this [m or line parameter] are not tested on their own.
constexpr double kShortestPiece = 1e-12;

// Roots of the quadratic |c + t w|^2 - radius^2 = 0.
void append_sphere_roots(const model::Vec3& c, const model::Vec3& w, double radius,
                         std::vector<double>& roots) {
  append_quadratic_roots(w.squaredNorm(), 2 * c.dot(w), c.squaredNorm() - radius * radius, roots);
}

// Roots of the linear n . (c + t w) = 0.
void append_plane_root(const model::Vec3& normal, const model::Vec3& c, const model::Vec3& w,
                       std::vector<double>& roots) {
  const double slope = normal.dot(w);
  if (std::abs(slope) > 1e-15) roots.push_back(-normal.dot(c) / slope);
}

// Roots where the angle between c + t w and `axis` equals acos(sigma): (k.q)^2 = sigma^2 |q|^2.
void append_cone_roots(const model::Vec3& axis, double sigma, const model::Vec3& c,
                       const model::Vec3& w, std::vector<double>& roots) {
  const double kc = axis.dot(c);
  const double kw = axis.dot(w);
  const double s2 = sigma * sigma;
  append_quadratic_roots(kw * kw - s2 * w.squaredNorm(), 2 * (kc * kw - s2 * c.dot(w)),
                         kc * kc - s2 * c.squaredNorm(), roots);
}

}  // namespace

MountedFov::MountedFov(const model::SensorMode& mode, const model::Pose3& T_robot_sensor,
                       const BodyOccluder& body, const model::MountLimits& limits)
    : mode_(&mode),
      T_robot_sensor_(T_robot_sensor),
      R_sensor_robot_(T_robot_sensor.linear().transpose()),
      origin_(T_robot_sensor.translation()),
      body_(&body) {
  if (limits.min_range || limits.max_range) {
    model::SensorMode limited = mode;
    limited.min_range = std::max(mode.min_range, limits.min_range.value_or(0.0));
    limited.max_range = std::min(mode.max_range, limits.max_range.value_or(mode.max_range));
    limited.max_range = std::max(limited.max_range, limited.min_range);  // an empty band
    limited_mode_ = std::make_shared<const model::SensorMode>(std::move(limited));
    mode_ = limited_mode_.get();
  }
  if (!limits.excluded_azimuths.empty() || !limits.excluded_boxes.empty()) {
    exclusions_ = std::make_shared<const MountExclusions>(limits, T_robot_sensor);
  }
  const model::FieldOfView& fov = mode.fov;
  tan_half_h_ = std::tan(fov.horizontal / 2);
  tan_half_v_ = std::tan(fov.vertical / 2);
  cos_half_apex_ = std::cos(fov.horizontal / 2);
  sin_elevation_min_ = std::sin(fov.elevation_min);
  sin_elevation_max_ = std::sin(fov.elevation_max);
  half_span_ = fov.horizontal / 2;
  bound_azimuths();
  if (body.parts()) {
    may_be_occluded_ = false;  // the body's own test is for cylinders and prisms
    shadow_ = std::make_shared<const SolidShadow>(
        *body.parts(), origin_,
        [this](const model::Vec3& a, const model::Vec3& b, const model::Vec3& c) {
          return triangle_may_matter(a, b, c);
        });
  } else {
    may_be_occluded_ = rays_can_reach(body);
  }
}

// A triangle hides a point of the FOV only if the sight line crosses it inside the FOV's cone
// and within max range. Each test below finds a convex region outside the FOV that holds all
// three corners, hence the whole triangle.
bool MountedFov::triangle_may_matter(const model::Vec3& a, const model::Vec3& b,
                                     const model::Vec3& c) const {
  const model::Vec3 q[3] = {R_sensor_robot_ * (a - origin_), R_sensor_robot_ * (b - origin_),
                            R_sensor_robot_ * (c - origin_)};
  const model::Vec3 centre = (q[0] + q[1] + q[2]) / 3;
  const double spread =
      std::max({(q[0] - centre).norm(), (q[1] - centre).norm(), (q[2] - centre).norm()});
  if (centre.norm() - spread > mode_->max_range) return false;
  const auto all_below = [&](const model::Vec3& normal, double sin_limit) {
    // All corners satisfy normal . q < sin_limit |q|.
    return std::all_of(std::begin(q), std::end(q),
                       [&](const model::Vec3& p) { return normal.dot(p) < sin_limit * p.norm(); });
  };
  switch (mode_->fov.shape) {
    case model::FovShape::pyramid:
    case model::FovShape::cone: {
      const bool cone = mode_->fov.shape == model::FovShape::cone;
      const double th = tan_half_h_;
      const double tv = cone ? tan_half_h_ : tan_half_v_;
      // Half-spaces bounding the pyramid (the cone lies inside its square pyramid).
      const model::Vec3 planes[5] = {{1, 0, 0}, {th, -1, 0}, {th, 1, 0}, {tv, 0, -1}, {tv, 0, 1}};
      for (const model::Vec3& n : planes) {
        if (all_below(n, 0.0)) return false;
      }
      return true;
    }
    case model::FovShape::band:
    case model::FovShape::planar:
      // Above the upper elevation cone (convex when its limit is >= 0), below the lower one.
      if (sin_elevation_max_ >= 0 && all_below(-model::Vec3::UnitZ(), -sin_elevation_max_)) {
        return false;
      }
      if (sin_elevation_min_ <= 0 && all_below(model::Vec3::UnitZ(), sin_elevation_min_)) {
        return false;
      }
      return true;
  }
  return true;
}

// A pyramid's (or cone's) volume lies inside the convex hull of its origin and the four
// corner rays at x = max range (|q| <= max implies q_x <= max). Seen from above, that hull
// spans the azimuths of its five points unless it encloses the robot's vertical axis.
void MountedFov::bound_azimuths() {
  if (mode_->fov.shape != model::FovShape::pyramid && mode_->fov.shape != model::FovShape::cone)
    return;
  const double far = mode_->max_range;
  const double tan_h =
      mode_->fov.shape == model::FovShape::cone ? std::tan(mode_->fov.horizontal / 2) : tan_half_h_;
  const double tan_v = mode_->fov.shape == model::FovShape::cone ? tan_h : tan_half_v_;
  std::vector<model::Vec2> hull_points = {origin_.head<2>()};
  for (const double sy : {-1.0, 1.0}) {
    for (const double sz : {-1.0, 1.0}) {
      hull_points.push_back(
          (T_robot_sensor_ * model::Vec3(far, sy * far * tan_h, sz * far * tan_v)).head<2>());
    }
  }
  // The hull encloses the axis when the points' azimuths leave no gap wider than pi.
  std::vector<double> azimuths;
  for (const model::Vec2& p : hull_points) {
    if (p.norm() < 1e-12) return;  // a point on the axis: every azimuth
    azimuths.push_back(std::atan2(p.y(), p.x()));
  }
  std::sort(azimuths.begin(), azimuths.end());
  double widest_gap = azimuths.front() + 2 * std::numbers::pi - azimuths.back();
  double gap_end = azimuths.front();
  for (std::size_t i = 1; i < azimuths.size(); ++i) {
    if (azimuths[i] - azimuths[i - 1] > widest_gap) {
      widest_gap = azimuths[i] - azimuths[i - 1];
      gap_end = azimuths[i];
    }
  }
  if (widest_gap <= std::numbers::pi) return;
  azimuth_from_ = gap_end;
  azimuth_span_ = 2 * std::numbers::pi - widest_gap;
}

bool MountedFov::may_reach_azimuth(double theta) const {
  if (azimuth_span_ >= 2 * std::numbers::pi) return true;
  const double offset = model::wrap_angle(theta - azimuth_from_);
  return offset <= azimuth_span_ + 1e-9;
}

// A ray leaving a sensor outside the cylinder while moving away from the robot's axis only
// gets farther from it, so it never meets the body. Directions of a pyramid are positive
// combinations of its four corner rays, so checking the corners covers them all; a cone's
// directions stay within its half-angle of the axis.
bool MountedFov::rays_can_reach(const BodyOccluder& body) const {
  const model::Vec2 o = origin_.head<2>();
  if (!body.is_cylinder() || o.norm() < body.radius()) return true;
  const model::Vec3 outward(o.x(), o.y(), 0.0);
  const model::Mat3& R_robot_sensor = T_robot_sensor_.linear();
  switch (mode_->fov.shape) {
    case model::FovShape::pyramid:
      for (const double sy : {-1.0, 1.0}) {
        for (const double sz : {-1.0, 1.0}) {
          const model::Vec3 corner =
              R_robot_sensor * model::Vec3(1.0, sy * tan_half_h_, sz * tan_half_v_);
          if (corner.dot(outward) < 0) return true;
        }
      }
      return false;
    case model::FovShape::cone: {
      const double axis_to_outward = std::acos(
          std::clamp((R_robot_sensor * model::Vec3::UnitX()).dot(outward.normalized()), -1.0, 1.0));
      return axis_to_outward + mode_->fov.horizontal / 2 > std::numbers::pi / 2;
    }
    case model::FovShape::band:
    case model::FovShape::planar: return true;
  }
  return true;
}

bool MountedFov::in_fov(const model::Vec3& q) const {
  const double distance = q.norm();
  if (distance < mode_->min_range || distance > mode_->max_range || distance == 0.0) return false;
  switch (mode_->fov.shape) {
    case model::FovShape::pyramid:
      return q.x() > 0 && std::abs(q.y()) <= tan_half_h_ * q.x() &&
             std::abs(q.z()) <= tan_half_v_ * q.x();
    case model::FovShape::cone: return q.x() >= cos_half_apex_ * distance;
    case model::FovShape::band:
    case model::FovShape::planar: {
      if (q.z() < sin_elevation_min_ * distance || q.z() > sin_elevation_max_ * distance) {
        return false;
      }
      if (half_span_ >= std::numbers::pi) return true;
      return std::abs(std::atan2(q.y(), q.x())) <= half_span_;
    }
  }
  return false;
}

bool MountedFov::sees(const model::Vec3& p_robot) const {
  return in_fov(R_sensor_robot_ * (p_robot - origin_)) &&
         !(may_be_occluded_ && body_->blocks(origin_, p_robot)) &&
         !(shadow_ && shadow_->blocks(p_robot)) && !(exclusions_ && exclusions_->excludes(p_robot));
}

void MountedFov::append_fov_roots(const model::Vec3& c, const model::Vec3& w,
                                  std::vector<double>& roots) const {
  append_sphere_roots(c, w, mode_->min_range, roots);
  append_sphere_roots(c, w, mode_->max_range, roots);
  switch (mode_->fov.shape) {
    case model::FovShape::pyramid:
      append_plane_root(model::Vec3(1, 0, 0), c, w, roots);
      for (const double sign : {-1.0, 1.0}) {
        append_plane_root(model::Vec3(tan_half_h_, sign, 0), c, w, roots);
        append_plane_root(model::Vec3(tan_half_v_, 0, sign), c, w, roots);
      }
      break;
    case model::FovShape::cone:
      append_cone_roots(model::Vec3::UnitX(), cos_half_apex_, c, w, roots);
      append_plane_root(model::Vec3::UnitX(), c, w, roots);
      break;
    case model::FovShape::band:
    case model::FovShape::planar:
      // Elevation limits are cones about the sensor's z axis; their sign flips at q_z = 0.
      append_cone_roots(model::Vec3::UnitZ(), sin_elevation_min_, c, w, roots);
      append_cone_roots(model::Vec3::UnitZ(), sin_elevation_max_, c, w, roots);
      append_plane_root(model::Vec3::UnitZ(), c, w, roots);
      if (half_span_ < std::numbers::pi) {  // azimuth limits: half-planes through the z axis
        append_plane_root(model::Vec3(-std::sin(half_span_), std::cos(half_span_), 0), c, w, roots);
        append_plane_root(model::Vec3(std::sin(half_span_), std::cos(half_span_), 0), c, w, roots);
        append_plane_root(model::Vec3::UnitX(), c, w, roots);
        append_plane_root(model::Vec3::UnitY(), c, w, roots);
      }
      break;
  }
}

IntervalSet MountedFov::covered_along(const model::Vec3& start, const model::Vec3& direction,
                                      double t_min, double t_max,
                                      std::optional<double> section_azimuth) const {
  const model::Vec3 c = R_sensor_robot_ * (start - origin_);
  const model::Vec3 w = R_sensor_robot_ * direction;
  thread_local std::vector<double> cuts;  // reused: this runs once per raster column
  cuts.clear();
  cuts.push_back(t_min);
  cuts.push_back(t_max);
  append_fov_roots(c, w, cuts);
  if (may_be_occluded_) body_->append_critical_parameters(origin_, start, direction, cuts);
  std::sort(cuts.begin(), cuts.end());
  IntervalSet covered;
  double previous = t_min;
  for (const double cut : cuts) {
    if (cut <= previous) continue;
    const double next = std::min(cut, t_max);
    if (next - previous > kShortestPiece) {
      const model::Vec3 mid = start + 0.5 * (previous + next) * direction;
      if (in_fov(R_sensor_robot_ * (mid - origin_)) &&
          !(may_be_occluded_ && body_->blocks(origin_, mid))) {
        covered.append(previous, next);
      }
    }
    previous = next;
    if (previous >= t_max) break;
  }
  if (shadow_ && !covered.empty()) {
    covered =
        covered.minus(shadow_->blocked_along(start, direction, covered.intervals().front().first,
                                             covered.intervals().back().second, section_azimuth));
  }
  if (exclusions_ && !covered.empty()) {
    covered = covered.minus(exclusions_->excluded_along(
        start, direction, covered.intervals().front().first, covered.intervals().back().second));
  }
  return covered;
}

}  // namespace rigdesign::geometry
