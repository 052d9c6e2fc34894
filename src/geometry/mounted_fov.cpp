#include "rigdesign/geometry/mounted_fov.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "rigdesign/geometry/bisection.hpp"
#include "rigdesign/model/line_crossings.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::geometry {
MountedFov::MountedFov(const model::SensorMode& mode, const model::Pose3& T_robot_sensor,
                       const BodyOccluder& body, const std::string& housing_link,
                       const model::MountLimits& limits,
                       const std::vector<model::BodyPart>& other_housings)
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
  shape_ = &mode_->fov.shape();
  bound_azimuths();
  // A description's parts and the other mounts' housings are exact shadows; a cylinder or
  // prism body keeps its own test.
  may_be_occluded_ = !body.parts() && rays_can_reach(body);
  if (body.parts() || !other_housings.empty()) {
    static const std::vector<model::BodyPart> kNoParts;
    shadow_ = std::make_shared<const SolidShadow>(
        body.parts() ? *body.parts() : kNoParts, other_housings, origin_, housing_link,
        [this](const model::Vec3& a, const model::Vec3& b, const model::Vec3& c) {
          return triangle_may_matter(a, b, c);
        });
    if (shadow_->empty()) shadow_.reset();  // nothing solid can hide what it sees
  }
}

// A triangle hides a point of the FOV only if the sight line crosses it inside the FOV's cone
// and within max range. Each test below finds a convex region outside the FOV that holds all
// three corners, hence the whole triangle.
bool MountedFov::triangle_may_matter(const model::Vec3& a, const model::Vec3& b,
                                     const model::Vec3& c) const {
  const std::array<model::Vec3, 3> q = {R_sensor_robot_ * (a - origin_),
                                        R_sensor_robot_ * (b - origin_),
                                        R_sensor_robot_ * (c - origin_)};
  const model::Vec3 centre = (q[0] + q[1] + q[2]) / 3;
  const double spread =
      std::max({(q[0] - centre).norm(), (q[1] - centre).norm(), (q[2] - centre).norm()});
  if (centre.norm() - spread > mode_->max_range) return false;
  return !shape_->excludes_triangle(q);
}

bool MountedFov::may_be_hidden_by(const model::TriangleMesh& mesh) const {
  return std::any_of(mesh.triangles.begin(), mesh.triangles.end(), [&](const auto& t) {
    return triangle_may_matter(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  });
}

// A camera's volume lies inside the convex hull of its origin and its bounding pyramid's four
// corner rays at x = max range (|q| <= max implies q_x <= max). Seen from above, that hull
// spans the azimuths of its five points unless it encloses the robot's vertical axis.
void MountedFov::bound_azimuths() {
  const auto corners = shape_->bounding_corners();
  if (!corners) return;
  const double far = mode_->max_range;
  std::vector<model::Vec2> hull_points = {origin_.head<2>()};
  for (const model::Vec3& corner : *corners) {
    hull_points.push_back((T_robot_sensor_ * (far * corner)).head<2>());
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
// gets farther from it, so it never meets the body.
bool MountedFov::rays_can_reach(const BodyOccluder& body) const {
  const model::Vec2 o = origin_.head<2>();
  if (!body.is_cylinder() || o.norm() < body.radius()) return true;
  return shape_->may_point_against(T_robot_sensor_.linear(), model::Vec3(o.x(), o.y(), 0.0));
}

bool MountedFov::in_fov(const model::Vec3& q) const {
  const double distance = q.norm();
  if (distance < mode_->min_range || distance > mode_->max_range || distance == 0.0) return false;
  return shape_->contains(q);
}

bool MountedFov::sees(const model::Vec3& p_robot) const {
  return in_fov(R_sensor_robot_ * (p_robot - origin_)) &&
         !(may_be_occluded_ && body_->blocks(origin_, p_robot)) &&
         !(shadow_ && shadow_->blocks(p_robot)) && !(exclusions_ && exclusions_->excludes(p_robot));
}

double MountedFov::robot_free_range(const model::Vec3& direction) const {
  const double reach = mode_->max_range;
  double free = std::numeric_limits<double>::infinity();
  if (may_be_occluded_ && body_->blocks(origin_, origin_ + reach * direction)) {
    // Along a ray from the origin, once the segment passes through the body it stays blocked:
    // the entry point by bisection (the silhouette's critical parameters degenerate when the
    // line of sight is the ray itself), halved until under 1e-12 m (at most 60 times).
    const int steps = std::clamp(static_cast<int>(std::ceil(std::log2(reach / 1e-12))), 0, 60);
    free = bisect(0.0, reach, steps, [&](double t) {
             return body_->blocks(origin_, origin_ + t * direction);
           }).second;
  }
  if (shadow_) {
    const IntervalSet hidden =
        shadow_->blocked_along(origin_, direction, 0.0, std::min(free, reach), std::nullopt);
    if (!hidden.empty()) free = std::min(free, hidden.intervals().front().first);
  }
  return free;
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
  model::append_sphere_crossings(c, w, mode_->min_range, cuts);
  model::append_sphere_crossings(c, w, mode_->max_range, cuts);
  shape_->append_boundary_crossings(c, w, cuts);
  if (may_be_occluded_) body_->append_critical_parameters(origin_, start, direction, cuts);
  IntervalSet covered;
  for_each_piece(cuts, t_min, t_max, [&](double low, double high) {
    const model::Vec3 mid = start + 0.5 * (low + high) * direction;
    if (in_fov(R_sensor_robot_ * (mid - origin_)) &&
        !(may_be_occluded_ && body_->blocks(origin_, mid))) {
      covered.append(low, high);
    }
  });
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
