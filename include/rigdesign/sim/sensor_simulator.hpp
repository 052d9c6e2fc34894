#pragma once
/// What one mounted sensor measures in a scene: its own ray pattern cast against the scene,
/// within its min and max range, with range noise from its sigma(d) and random dropout
/// (DESIGN.md section 6). Seeded: the same seed gives the same cloud.
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/sim/ray_caster.hpp"

namespace rigdesign::sim {

/// Unit ray directions in the sensor frame (x forward): a pinhole pixel grid for pyramid
/// cameras (pixel centres, evenly spaced in the image plane), rings of a spinning lidar
/// (one row per vertical step from the lowest beam, one column per horizontal step), one
/// row for a 2D scanner's fan, a pixel grid clipped to the circle for a cone. Non-repetitive
/// scanners (Livox) get a grid at their effective step.
std::vector<model::Vec3> ray_pattern(const model::SensorMode& mode);

struct SimulationSettings {
  double dropout = 0.0;   ///< share of rays that return nothing, in [0, 1)
  bool add_noise = true;  ///< range noise N(0, sigma(d)^2) along each ray
  /// Points in the sensor's own frame as its driver publishes them (else the world frame):
  /// a camera's optical frame (REP-103: z forward, x right, y down), a lidar's x-forward
  /// frame. `filter --mount` assumes the same by default.
  bool sensor_frame = false;
  /// An organised cloud, as depth cameras publish one: every ray keeps its place, a ray that
  /// returns nothing gives a NaN point (what mean pooling of the depth image needs).
  bool keep_misses = false;
  /// A camera whose mode has depth_matching reports, per pixel, the depth that fills most of
  /// its matching window (depth_matching.hpp): thin objects at range vanish. False: every ray
  /// returns its own first hit.
  bool depth_matching = true;
};

/// One frame. `T_world_sensor` places the sensor; the cloud's origin and orientation record
/// the sensor pose in the cloud's frame. `free_ranges` (robot_occlusion.hpp), one per ray, is
/// where the sensor's own robot hides each ray: a ray whose scene hit lies beyond it ends on the
/// robot and returns nothing, as the export's self-filter drops such returns. Empty: the robot
/// hides nothing (a sensor on its own, as paper 3's cell has them).
model::PointCloud simulate_frame(const RayCaster& scene, const model::SensorMode& mode,
                                 const std::vector<model::Vec3>& rays,
                                 const model::Pose3& T_world_sensor,
                                 const SimulationSettings& settings, std::mt19937_64& rng,
                                 std::span<const double> free_ranges = {});

}  // namespace rigdesign::sim
