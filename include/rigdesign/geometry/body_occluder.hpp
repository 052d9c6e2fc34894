#pragma once
/// The robot body as an occluder: a vertical cylinder (radius r) or footprint prism from the
/// floor to height h. A sensor sees nothing through it.
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::geometry {

class BodyOccluder {
 public:
  explicit BodyOccluder(const model::RobotBody& body);

  /// True when the open segment from `origin` to `point` passes through the body's interior.
  bool blocks(const model::Vec3& origin, const model::Vec3& point) const;

  /// Parameters t at which the segment from `origin` to `start + t * direction` can start or
  /// stop passing through the body: where the line of sight grazes the body's silhouette
  /// (tangent planes of the side, the rims or edges of the top and bottom faces). Between two
  /// consecutive values, `blocks` does not change.
  void append_critical_parameters(const model::Vec3& origin, const model::Vec3& start,
                                  const model::Vec3& direction,
                                  std::vector<double>& parameters) const;

  /// True when `point` is strictly inside the body (a sensor there would see nothing).
  bool contains(const model::Vec3& point) const;

  /// Distance from the vertical axis to the body's side along azimuth theta [m].
  double radius_at(double theta) const;

  double height() const { return height_; }
  bool is_cylinder() const { return footprint_.empty(); }
  double radius() const { return radius_; }

 private:
  double radius_ = 0.0;
  double height_ = 0.0;
  std::vector<model::Vec2> footprint_;  // empty for a cylinder
};

/// Real roots of a t^2 + b t + c = 0 (one root when a is negligible) appended to `roots`.
void append_quadratic_roots(double a, double b, double c, std::vector<double>& roots);

}  // namespace rigdesign::geometry
