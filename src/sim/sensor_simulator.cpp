#include "rigdesign/sim/sensor_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rigdesign/model/optical_frame.hpp"
#include "rigdesign/sim/depth_matching.hpp"
#include "rigdesign/sim/mean_pooling.hpp"

namespace rigdesign::sim {
std::vector<model::Vec3> ray_pattern(const model::SensorMode& mode) {
  // A single-row scanner has no vertical step: one step spans its whole height.
  return mode.fov.shape().ray_pattern(mode.angular_resolution_h,
                                      mode.angular_resolution_v.value_or(mode.fov.vertical()));
}

namespace {

// A camera's rays as a row-major pixel grid whose rows and columns `step_rows` and
// `step_columns` apart are a third of the depth-matching window apart: the window's rays are
// then the grid's own (at the sensor's native resolution; a decimated pattern casts its own).
struct WindowGrid {
  int columns = 0;  // 0: not usable
  int rows = 0;
  int step_columns = 0;
  int step_rows = 0;
  bool inside(std::size_t r) const {
    const int row = static_cast<int>(r / static_cast<std::size_t>(columns));
    const int column = static_cast<int>(r % static_cast<std::size_t>(columns));
    return row >= step_rows && row + step_rows < rows && column >= step_columns &&
           column + step_columns < columns;
  }
};

WindowGrid window_grid(const model::SensorMode& mode, const std::vector<model::Vec3>& rays,
                       const model::DepthMatching& matching) {
  WindowGrid grid;
  const int columns = pixel_grid_columns(rays);
  if (columns <= 0 || !mode.angular_resolution_v) return grid;
  const double third = matching.window_angle / 3.0;
  const double h = third / mode.angular_resolution_h;
  const double v = third / *mode.angular_resolution_v;
  // Only where a third of the window is a whole number of pixels, within a tenth of a pixel.
  if (!(h >= 0.9 && v >= 0.9) || std::abs(h - std::round(h)) > 0.1 ||
      std::abs(v - std::round(v)) > 0.1)
    return grid;
  grid.columns = columns;
  grid.rows = static_cast<int>(rays.size() / static_cast<std::size_t>(columns));
  grid.step_columns = static_cast<int>(std::lround(h));
  grid.step_rows = static_cast<int>(std::lround(v));
  return grid;
}

// matched_range with the window's rays read from the grid's first hits, for a ray `r` inside
// the grid (WindowGrid::inside).
std::optional<double> grid_matched_range(const WindowGrid& grid,
                                         const std::function<double(std::size_t)>& range_of,
                                         std::size_t r, double centre,
                                         const model::DepthMatching& matching) {
  const auto sample = [&](int row, int column) {
    const long offset = static_cast<long>(row) * grid.step_rows * grid.columns +
                        static_cast<long>(column) * grid.step_columns;
    return range_of(static_cast<std::size_t>(static_cast<long>(r) + offset));
  };
  return window_majority(centre, sample, matching.baseline_focal);
}

}  // namespace

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
  const WindowGrid grid = matching ? window_grid(mode, rays, *matching) : WindowGrid{};
  // With the window's rays on the pixel grid, every ray's first hit first (infinity: none);
  // no extra rays are cast but at the image's border.
  std::vector<double> grid_hits;
  if (grid.columns > 0) {
    grid_hits.resize(rays.size());
    for (std::size_t r = 0; r < rays.size(); ++r) {
      grid_hits[r] = scene.first_hit(origin, R_world_sensor * rays[r]).value_or(kNoRobot);
    }
  }
  // A window ray's range: where the robot stops it, if it does before the scene.
  const auto window_range = [&](std::size_t i) {
    return robot ? std::min(grid_hits[i], free_ranges[i]) : grid_hits[i];
  };
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
    const std::optional<double> hit = grid_hits.empty() ? scene.first_hit(origin, direction)
                                      : std::isfinite(grid_hits[r])
                                          ? std::optional<double>(grid_hits[r])
                                          : std::nullopt;
    // The robot (its body, parts, other housings, supports) stops the ray first.
    const bool on_robot = robot && hit && *hit > free_ranges[r];
    if (on_robot || !hit) {
      no_return();
      continue;
    }
    // A window-matching camera reports the depth that fills most of the pixel's window.
    const double free_range = robot ? free_ranges[r] : kNoRobot;
    const bool from_grid = grid.columns > 0 && grid.inside(r);
    const std::optional<double> seen =
        !matching   ? hit
        : from_grid ? grid_matched_range(grid, window_range, r, *hit, *matching)
                    : matched_range(scene, origin, direction, up, *hit, *matching, free_range);
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
