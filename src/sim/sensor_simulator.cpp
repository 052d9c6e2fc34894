#include "rigdesign/sim/sensor_simulator.hpp"

#include "rigdesign/model/optical_frame.hpp"

#include <cmath>
#include <numbers>

namespace rigdesign::sim {
namespace {

int steps(double span, double step) {
  return std::max(1, static_cast<int>(std::lround(span / step)));
}

// Pixel centres of a pinhole camera: evenly spaced on the image plane x = 1.
std::vector<model::Vec3> pinhole_grid(double horizontal, double vertical, int columns, int rows,
                                      bool circular) {
  std::vector<model::Vec3> rays;
  const double half_width = std::tan(horizontal / 2);
  const double half_height = std::tan(vertical / 2);
  rays.reserve(static_cast<std::size_t>(columns) * rows);
  for (int row = 0; row < rows; ++row) {
    const double z = half_height * (1 - 2 * (row + 0.5) / rows);  // top row first, like an image
    for (int column = 0; column < columns; ++column) {
      const double y = half_width * (1 - 2 * (column + 0.5) / columns);  // left first
      if (circular && y * y + z * z > half_width * half_width) continue;
      rays.push_back(model::Vec3(1.0, y, z).normalized());
    }
  }
  return rays;
}

}  // namespace

std::vector<model::Vec3> ray_pattern(const model::SensorMode& mode) {
  const model::FieldOfView& fov = mode.fov;
  const double step_h = mode.angular_resolution_h;
  const double step_v = mode.angular_resolution_v.value_or(fov.vertical);
  switch (fov.shape) {
    case model::FovShape::pyramid:
      return pinhole_grid(fov.horizontal, fov.vertical, steps(fov.horizontal, step_h),
                          steps(fov.vertical, step_v), false);
    case model::FovShape::cone:
      return pinhole_grid(fov.horizontal, fov.horizontal, steps(fov.horizontal, step_h),
                          steps(fov.horizontal, step_v), true);
    case model::FovShape::band:
    case model::FovShape::planar: {
      std::vector<model::Vec3> rays;
      const bool full_circle = fov.horizontal >= 2 * std::numbers::pi - 1e-9;
      // A full turn has as many columns as steps; a sector includes both edges.
      const int columns = steps(fov.horizontal, step_h) + (full_circle ? 0 : 1);
      const int rows = fov.shape == model::FovShape::planar ? 1 : steps(fov.vertical, step_v) + 1;
      for (int row = 0; row < rows; ++row) {
        const double elevation = rows == 1 ? 0.5 * (fov.elevation_min + fov.elevation_max)
                                           : fov.elevation_min + fov.vertical * row / (rows - 1);
        for (int column = 0; column < columns; ++column) {
          const double azimuth =
              full_circle ? 2 * std::numbers::pi * column / columns - std::numbers::pi
                          : -fov.horizontal / 2 + fov.horizontal * column / (columns - 1);
          rays.emplace_back(std::cos(elevation) * std::cos(azimuth),
                            std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
        }
      }
      return rays;
    }
  }
  return {};
}

model::PointCloud simulate_frame(const RayCaster& scene, const model::SensorMode& mode,
                                 const std::vector<model::Vec3>& rays,
                                 const model::Pose3& T_world_sensor,
                                 const SimulationSettings& settings, std::mt19937_64& rng) {
  model::PointCloud cloud;
  cloud.points.reserve(rays.size());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  const model::Vec3 origin = T_world_sensor.translation();
  const model::Mat3 R_world_sensor = T_world_sensor.linear();
  for (const model::Vec3& ray : rays) {
    // Draw both numbers for every ray so a hit or miss elsewhere never shifts the sequence.
    const double lost = unit(rng);
    const double normal = gaussian(rng);
    if (lost < settings.dropout) continue;
    const model::Vec3 direction = R_world_sensor * ray;
    const std::optional<double> hit = scene.first_hit(origin, direction);
    if (!hit || *hit < mode.min_range || *hit > mode.max_range) continue;
    const double range = *hit + (settings.add_noise ? normal * mode.noise.sigma(*hit) : 0.0);
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
