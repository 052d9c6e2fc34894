#pragma once
/// A sensor mode's field of view placed on the robot: its FOV shape (model::FovShape) between the
/// min and max range measured from the sensor origin (spherical caps), seen past the robot body.
/// Gives exact coverage along any line in the robot frame.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/interval_set.hpp"
#include "rigdesign/geometry/mount_exclusions.hpp"
#include "rigdesign/geometry/solid_shadow.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::geometry {

class MountedFov {
 public:
  /// `housing_link`: the description link that is the sensor's own housing (model::Mount's),
  /// the only collision geometry it sees through; empty: none. `limits` (a deployed stack's
  /// range limits and filters) narrow the mode's range and drop their regions; empty for the
  /// design itself. `other_housings`: the other mounts' housings in the robot frame
  /// (geometry/housing_geometry.hpp), solid for this sensor; read here, not kept.
  MountedFov(const model::SensorMode& mode, const model::Pose3& T_robot_sensor,
             const BodyOccluder& body, const std::string& housing_link,
             const model::MountLimits& limits = {},
             const std::vector<model::BodyPart>& other_housings = {});

  /// True when the sensor measures `p_robot`: inside its FOV and range and not behind the body.
  bool sees(const model::Vec3& p_robot) const;

  /// The parameters t in [t_min, t_max] at which the line start + t * direction is seen,
  /// exact up to floating point: every t where coverage can change (a root of the range
  /// spheres, FOV boundary planes and cones, or the body's silhouette) splits the line and
  /// each piece is tested once. A description's collision parts are subtracted as exact
  /// shadow intervals; `section_azimuth` (the line lies in that vertical half-plane) lets the
  /// shadow try only the triangles that reach it.
  IntervalSet covered_along(const model::Vec3& start, const model::Vec3& direction, double t_min,
                            double t_max, std::optional<double> section_azimuth = {}) const;

  const model::Vec3& origin() const { return origin_; }
  /// False when the FOV certainly misses the vertical half-plane at azimuth `theta` (a
  /// conservative test: true does not promise coverage).
  bool may_reach_azimuth(double theta) const;

  /// False when no triangle of `mesh` (robot frame) can hide anything this sensor sees (a
  /// conservative test: true promises nothing).
  bool may_be_hidden_by(const model::TriangleMesh& mesh) const;

  /// False when no direction in the FOV can reach the body, so occlusion can be skipped.
  /// How far [m] a ray from the sensor origin along the unit `direction` (robot frame) goes
  /// before the robot hides the rest of it: the body, the solid parts, the other housings and
  /// the supports (not the deployed limits). +infinity when nothing of the robot is in its way
  /// within the mode's max range; 0 for a buried sensor.
  double robot_free_range(const model::Vec3& direction) const;
  bool may_be_occluded() const { return may_be_occluded_; }
  const model::Pose3& pose() const { return T_robot_sensor_; }
  const model::SensorMode& mode() const { return *mode_; }
  /// What the deployed filters drop, or nullptr.
  const MountExclusions* exclusions() const { return exclusions_.get(); }
  /// The shadow of the body's collision parts and the other housings from this sensor;
  /// nullptr when only a cylinder or prism body is solid.
  const SolidShadow* shadow() const { return shadow_.get(); }

 private:
  bool in_fov(const model::Vec3& q_sensor) const;
  bool rays_can_reach(const BodyOccluder& body) const;
  bool triangle_may_matter(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c) const;

  const model::SensorMode* mode_;
  std::shared_ptr<const model::SensorMode> limited_mode_;  // the mode with a deployed range band
  std::shared_ptr<const MountExclusions> exclusions_;      // null without filters
  model::Pose3 T_robot_sensor_;
  model::Mat3 R_sensor_robot_;
  model::Vec3 origin_;
  const BodyOccluder* body_;
  std::shared_ptr<const SolidShadow> shadow_;  // shared: MountedFov is copied into lists
  const model::FovShape* shape_;               // the mode's shape: shared by every copy of the mode
  bool may_be_occluded_ = true;
  // Azimuths (about the robot's vertical axis) the FOV can reach: [from, from + span].
  double azimuth_from_ = 0.0;
  double azimuth_span_ = 7.0;  // > 2 pi: every azimuth
  void bound_azimuths();
};

}  // namespace rigdesign::geometry
