#pragma once
/// A field-of-view shape: the set of directions a sensor measures, in the sensor frame (x
/// forward along the optical axis, y left, z up). Everything that differs between shapes is a
/// virtual function here, so a new shape is one new class (plus its reader in
/// io/config/fov_readers.cpp) and the compiler names every function it must provide.
/// Angles are radians.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// The rectangle of two angles (u, v) [rad] that parametrises a shape's directions
/// (`FovShape::direction`), and where that map degenerates.
struct AngularDomain {
  double u_min = 0.0;
  double u_max = 0.0;
  double v_min = 0.0;
  double v_max = 0.0;
  bool wraps_u = false;        ///< u spans a full turn: u_max is the same direction as u_min
  bool pole_at_v_min = false;  ///< every u gives one direction at v_min
  bool pole_at_v_max = false;  ///< ... at v_max
};

/// An angle as files and reports name it (`key` ends in `_deg`); the value in radians.
struct NamedAngle {
  std::string_view key;
  double radians = 0.0;
};

class FovShape {
 public:
  virtual ~FovShape() = default;

  /// The name files and reports use ("pyramid", "cone", "band", "planar").
  virtual std::string_view name() const = 0;
  /// Rays on an image grid (a camera) rather than scanned rows: decides decimation, the
  /// optical frame and how the rays are drawn.
  virtual bool is_camera() const = 0;
  /// A 2D scanner: one row of rays, published as a sensor_msgs/LaserScan.
  virtual bool is_planar_scan() const = 0;

  /// [rad] full horizontal angle (azimuth span for scanners, apex angle for a cone).
  double horizontal() const { return horizontal_; }
  /// [rad] full vertical angle (elevation_max - elevation_min for scanners).
  double vertical() const { return vertical_; }
  /// [rad] lowest and highest elevation above the sensor's x-y plane.
  double elevation_min() const { return elevation_min_; }
  double elevation_max() const { return elevation_max_; }

  /// The (u, v) rectangle `direction` maps onto the shape's directions.
  virtual AngularDomain domain() const = 0;
  /// The unit direction at angles (u, v) of `domain()`.
  virtual Vec3 direction(double u, double v) const = 0;
  /// Whether the non-zero vector `q_sensor` points inside the field of view.
  virtual bool contains(const Vec3& q_sensor) const = 0;
  /// Appends every t at which the line c + t w (sensor frame) may cross the boundary of the
  /// FOV's cone of directions (its planes and cones through the origin). Extra values are
  /// harmless: callers test each piece between consecutive values.
  virtual void append_boundary_crossings(const Vec3& c, const Vec3& w,
                                         std::vector<double>& crossings) const = 0;
  /// True when a convex region outside the FOV's cone of directions holds all three points
  /// (sensor frame), so a triangle with these corners hides nothing the sensor would see.
  virtual bool excludes_triangle(const std::array<Vec3, 3>& q_sensor) const = 0;
  /// Whether some direction of the FOV, turned into the robot frame by `R_robot_sensor`, has
  /// a negative component along `outward`; true when the shape cannot tell (conservative).
  virtual bool may_point_against(const Mat3& R_robot_sensor, const Vec3& outward) const = 0;
  /// Four corner rays (x = 1) of a pyramid that holds every direction of the FOV, or nothing
  /// when the FOV is not inside such a pyramid (scanners).
  virtual std::optional<std::array<Vec3, 4>> bounding_corners() const = 0;
  /// The unit directions a sensor of this shape measures, `step_h` and `step_v` [rad] apart,
  /// in the order its driver publishes them.
  virtual std::vector<Vec3> ray_pattern(double step_h, double step_v) const = 0;
  /// The angles that describe the shape in reports, keyed as in files.
  virtual std::vector<NamedAngle> report_angles() const = 0;
  /// One line in degrees: "87 x 58", "cone 90", "360 (-15..15)", "270 planar".
  virtual std::string summary_deg() const = 0;

  /// The sine of the steepest downward direction of the FOV once turned into the robot frame
  /// by `R_robot_sensor` (<= 0: no ray points down), from a 65 x 65 grid over `domain()`,
  /// edges included.
  double steepest_down(const Mat3& R_robot_sensor) const;

 protected:
  FovShape(double horizontal, double vertical, double elevation_min, double elevation_max)
      : horizontal_(horizontal),
        vertical_(vertical),
        elevation_min_(elevation_min),
        elevation_max_(elevation_max) {}

 private:
  double horizontal_;
  double vertical_;
  double elevation_min_;
  double elevation_max_;
};

/// A camera frustum: `horizontal` x `vertical` full angles about the x axis.
std::shared_ptr<const FovShape> pyramid_fov(double horizontal, double vertical);
/// A circular camera: `apex` is the full apex angle about the x axis.
std::shared_ptr<const FovShape> cone_fov(double apex);
/// A spinning lidar: azimuth span `horizontal` centred on x, elevations in [low, high].
std::shared_ptr<const FovShape> band_fov(double horizontal, double elevation_min,
                                         double elevation_max);
/// A 2D scanner: aperture `horizontal` centred on x, a wedge `divergence` thick about the
/// x-y plane (the beam's divergence).
std::shared_ptr<const FovShape> planar_fov(double horizontal, double divergence);

/// A sensor mode's field of view: a shared, immutable shape (never null; a default one is an
/// empty pyramid).
class FieldOfView {
 public:
  FieldOfView();
  explicit FieldOfView(std::shared_ptr<const FovShape> shape);

  const FovShape& shape() const { return *shape_; }
  double horizontal() const { return shape_->horizontal(); }
  double vertical() const { return shape_->vertical(); }
  double elevation_min() const { return shape_->elevation_min(); }
  double elevation_max() const { return shape_->elevation_max(); }
  /// The horizontal angle is a whole turn (within 1e-6 rad of 2 pi, as files round it): the
  /// first and last rays coincide, which exporters must not count twice.
  bool full_turn() const { return horizontal() >= kFullTurn - kFullTurnTolerance; }

 private:
  static constexpr double kFullTurn = 6.283185307179586;
  static constexpr double kFullTurnTolerance = 1e-6;  // [rad]
  std::shared_ptr<const FovShape> shape_;
};

}  // namespace rigdesign::model
