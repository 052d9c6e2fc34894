#pragma once
/// The robot body as an occluder: a vertical cylinder (radius r) or footprint prism from the
/// floor to height h. A sensor sees nothing through it. For a body made of a description's
/// collision parts, occlusion is per sensor (SolidShadow, built by MountedFov) and this class
/// gives the body's outline and extent; `blocks` and the critical parameters then report
/// nothing. Holds a pointer to the body's parts: the RobotBody must outlive it.
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

  /// True when `point` is strictly inside the cylinder or prism (a sensor there would see
  /// nothing). Always false for collision parts: a sensor inside one is inside its own
  /// housing, which SolidShadow leaves out for that sensor.
  bool contains(const model::Vec3& point) const;

  /// Distance from the vertical axis to the body's outline along azimuth theta [m]: the
  /// farthest point of the body's horizontal projection on that ray.
  double radius_at(double theta) const;

  double height() const { return height_; }
  /// Top of the area to perceive [m] (the body's height unless the requirements say).
  double area_top() const { return area_top_; }
  bool is_cylinder() const { return footprint_.empty() && !parts_; }
  /// The collision parts, or nullptr for a cylinder or prism body.
  const std::vector<model::BodyPart>* parts() const { return parts_; }
  double radius() const { return radius_; }

 private:
  double radius_ = 0.0;
  double height_ = 0.0;
  double area_top_ = 0.0;
  std::vector<model::Vec2> footprint_;  // empty for a cylinder
  const std::vector<model::BodyPart>* parts_ = nullptr;
  // The parts' projected triangle edges, binned by the azimuths they span about the axis, so
  // that the outline along one azimuth tries only the edges that can cross it.
  struct Edge {
    model::Vec2 a;
    model::Vec2 b;
  };
  std::vector<std::vector<Edge>> outline_bins_;
  void bin_outline_edges();
  double outline_radius(double theta) const;
};

}  // namespace rigdesign::geometry
