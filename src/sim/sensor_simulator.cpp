#include "rigdesign/sim/sensor_simulator.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rigdesign/model/optical_frame.hpp"
#include "rigdesign/sim/depth_matching.hpp"

namespace rigdesign::sim {
std::vector<model::Vec3> ray_pattern(const model::SensorMode& mode) {
  // A single-row scanner has no vertical step: one step spans its whole height.
  return mode.fov.shape().ray_pattern(mode.angular_resolution_h,
                                      mode.angular_resolution_v.value_or(mode.fov.vertical()));
}

model::PointCloud simulate_frame(const RayCaster& scene, const model::SensorMode& mode,
                                 const std::vector<model::Vec3>& rays,
                                 const model::Pose3& T_world_sensor,
                                 const SimulationSettings& settings, std::mt19937_64& rng,
                                 std::span<const double> free_ranges) {
  model::PointCloud cloud;
  cloud.points.reserve(rays.size());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  constexpr float kNoReturn = std::numeric_limits<float>::quiet_NaN();
  const auto no_return = [&] {
    if (settings.keep_misses) cloud.points.emplace_back(kNoReturn, kNoReturn, kNoReturn);
  };
  const model::Vec3 origin = T_world_sensor.translation();
  const model::Mat3 R_world_sensor = T_world_sensor.linear();
  // One free range per ray, or none: a pattern made for another mode must not pass unnoticed.
  if (!free_ranges.empty() && free_ranges.size() != rays.size())
    throw std::logic_error("simulate_frame: " + std::to_string(free_ranges.size()) +
                           " free ranges for " + std::to_string(rays.size()) + " rays");
  const bool robot = !free_ranges.empty();
  const model::DepthMatching* matching =
      settings.depth_matching && mode.depth_matching && mode.is_camera() ? &*mode.depth_matching
                                                                         : nullptr;
  const model::Vec3 up = R_world_sensor.col(2);
  constexpr double kNoRobot = std::numeric_limits<double>::infinity();
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const model::Vec3& ray = rays[r];
    // Draw both numbers for every ray so a hit or miss elsewhere never shifts the sequence.
    const double lost = unit(rng);
    const double normal = gaussian(rng);
    if (lost < settings.dropout) {
      no_return();
      continue;
    }
    const model::Vec3 direction = R_world_sensor * ray;
    const std::optional<double> hit = scene.first_hit(origin, direction);
    // The robot (its body, parts, other housings, supports) stops the ray first.
    const bool on_robot = robot && hit && *hit > free_ranges[r];
    if (on_robot || !hit) {
      no_return();
      continue;
    }
    // A window-matching camera reports the depth that fills most of the pixel's window.
    const std::optional<double> seen =
        matching ? matched_range(scene, origin, direction, up, *hit, *matching,
                                 robot ? free_ranges[r] : kNoRobot)
                 : hit;
    if (!seen || *seen < mode.min_range || *seen > mode.max_range) {
      no_return();
      continue;
    }
    const double range = *seen + (settings.add_noise ? normal * mode.noise.sigma(*seen) : 0.0);
    const model::Vec3 point =
        settings.sensor_frame ? model::Vec3(ray * range) : model::Vec3(origin + direction * range);
    cloud.points.push_back(point.cast<float>());
  }
  if (settings.sensor_frame) {
    cloud.origin = model::Point3f::Zero();
    if (mode.is_camera()) {  // as camera drivers publish: the optical frame
      const Eigen::Matrix3f R_optical_sensor =
          model::T_sensor_optical().linear().transpose().cast<float>();
      for (model::Point3f& p : cloud.points) p = R_optical_sensor * p;
    }
  } else {
    cloud.origin = origin.cast<float>();
    cloud.orientation = Eigen::Quaternionf(R_world_sensor.cast<float>());
  }
  return cloud;
}

}  // namespace rigdesign::sim
