#pragma once
/// What a robot description's collision geometry hides from one sensor: every point p whose
/// sight line from the sensor origin o passes through a part. A triangle's shadow is the
/// cone from o through it, beyond its plane: four half-spaces, so along any line it is one
/// interval, found exactly by four linear inequalities. A vertical cylinder is convex, so its
/// shadow along a line is one interval too, bounded by the line of sight's tangencies (the
/// side's tangent planes and the rims' cones). Coverage along a line is the FOV's intervals
/// minus the union of these: exact up to floating point, with no sampling.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/interval_set.hpp"
#include "rigdesign/geometry/winding_number.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::geometry {

/// Decides whether a triangle (robot frame) could hide anything the sensor would otherwise
/// see; false lets the shadow skip it (a conservative test: true promises nothing).
using TriangleTest =
    std::function<bool(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c)>;

class SolidShadow {
 public:
  /// `parts` (a description's collision geometry) and `other_housings` (the other mounts'
  /// housings, geometry/housing_geometry.hpp) in the robot frame. The parts of link `housing`
  /// (the sensor's own housing in the description, model/sensor_housing.hpp; empty: none) cast
  /// no shadow for this sensor; every other part is solid. A sensor whose origin is inside one
  /// of them is buried: it sees nothing.
  SolidShadow(const std::vector<model::BodyPart>& parts,
              const std::vector<model::BodyPart>& other_housings, const model::Vec3& origin,
              const std::string& housing, const TriangleTest& may_matter);

  /// The parameters t in [t_min, t_max] at which start + t * direction is hidden. When the
  /// line lies in the vertical half-plane at azimuth `section_azimuth` (about the robot's
  /// vertical axis), only triangles whose shadow reaches that half-plane are tried.
  IntervalSet blocked_along(const model::Vec3& start, const model::Vec3& direction, double t_min,
                            double t_max, std::optional<double> section_azimuth) const;

  /// True when `point` is hidden.
  bool blocks(const model::Vec3& point) const;

  /// The link of the part the origin is inside of, or empty: the sensor is not buried.
  const std::string& buried_in() const { return buried_in_; }
  std::size_t triangle_count() const { return triangles_.size(); }
  bool empty() const { return triangles_.empty() && cylinders_.empty() && buried_in_.empty(); }

 private:
  // n . (p - o) >= offset for each of four planes: three through o and an edge, one the
  // triangle's own plane (p beyond it).
  struct TriangleShadow {
    model::Vec3 normal[4];
    double offset[4];
  };
  struct CylinderShadow {
    BodyOccluder solid;    // the cylinder as a body standing on its own floor
    model::Vec3 to_local;  // subtract to move robot-frame points into its frame
  };

  // False when the origin is inside the part (then the sensor is buried).
  bool add_part(const model::BodyPart& part, const TriangleTest& may_matter);
  void add_triangle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c);
  void bin_by_azimuth(std::size_t index, const model::Vec3 corners[3]);
  const std::vector<int>& candidates(std::optional<double> section_azimuth) const;

  model::Vec3 origin_;
  std::vector<TriangleShadow> triangles_;
  std::vector<CylinderShadow> cylinders_;
  std::vector<std::vector<int>> bins_;  // per azimuth bin: triangles whose shadow reaches it
  std::vector<int> all_;
  std::string buried_in_;
};

}  // namespace rigdesign::geometry
