// check_costmap_params: bad costmap settings are bad input (exit 2), named by field.
#include <cmath>
#include <cstdint>
#include <limits>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::costmap {
namespace {

// Cells per window axis: 2^15 keeps cell indices, counts and allocations sane (a 1 km window
// at 3 cm); larger windows are a typo more often than a need.
constexpr double kMaxCellsPerAxis = 32768.0;
// Voxels per window: 2^31 bytes is already a lot for a local map.
constexpr double kMaxVoxels = 2147483648.0;
// Entries of the inflation layer's cost table, (inflation radius / resolution)^2: 10 MB. A
// radius of 1e300 m asked for more memory than exists (issue 53 item 3).
constexpr double kMaxInflationTable = 1e7;

struct Checker {
  const model::SourceLocation& where;
  const std::string& prefix;
  model::Diagnostics diagnostics;

  void require(bool ok, const std::string& field, double value, const std::string& expected) {
    if (!ok)
      diagnostics.error(where, prefix + field, "is " + model::format_number(value), expected);
  }
};

bool finite_positive(double value) {
  return std::isfinite(value) && value > 0;
}
bool finite_non_negative(double value) {
  return std::isfinite(value) && value >= 0;
}

void check_window(Checker& c, const CostmapParams& p) {
  c.require(finite_positive(p.resolution), "resolution", p.resolution,
            "a cell size in metres, > 0");
  c.require(finite_non_negative(p.robot_radius), "robot_radius", p.robot_radius,
            "a radius in metres, >= 0");
  const double footprint = 2 * p.robot_radius;
  for (const auto& [name, size] : {std::pair{"size_x", p.size_x}, std::pair{"size_y", p.size_y}}) {
    if (!finite_positive(size)) {
      c.require(false, name, size, "a window side in metres, > 0");
    } else if (size < footprint) {
      c.diagnostics.error(
          c.where, c.prefix + name,
          "is " + model::format_number(size) + " m, smaller than the robot's footprint (" +
              model::format_number(footprint) + " m across)",
          "a window side of at least 2 x robot_radius = " + model::format_number(footprint) + " m");
    } else if (finite_positive(p.resolution)) {
      c.require(size / p.resolution <= kMaxCellsPerAxis, name, size,
                "at most " + model::format_number(kMaxCellsPerAxis, 7) + " cells of " +
                    model::format_number(p.resolution) + " m");
    }
  }
}

void check_voxel(Checker& c, const CostmapParams& p) {
  const VoxelLayerParams& v = p.voxel;
  c.require(std::isfinite(v.z_min), "voxel.z_min", v.z_min, "a height in metres");
  c.require(std::isfinite(v.z_max) && v.z_max > v.z_min, "voxel.z_max", v.z_max,
            "a height in metres above voxel.z_min (" + model::format_number(v.z_min) + ")");
  c.require(finite_positive(v.z_resolution), "voxel.z_resolution", v.z_resolution,
            "a voxel height in metres, > 0");
  c.require(v.unknown_threshold >= 0, "voxel.unknown_threshold", v.unknown_threshold,
            "a voxel count, >= 0");
  if (p.layer == ObstacleLayerKind::voxel && finite_positive(p.resolution) &&
      finite_positive(v.z_resolution) && v.z_max > v.z_min) {
    const double voxels = std::ceil(p.size_x / p.resolution) * std::ceil(p.size_y / p.resolution) *
                          std::ceil((v.z_max - v.z_min) / v.z_resolution);
    c.require(
        voxels <= kMaxVoxels, "voxel.z_resolution", v.z_resolution,
        "a window of at most 2^31 voxels (this one has " + model::format_number(voxels, 3) + ")");
  }
}

void check_hit(Checker& c, const HitLayerParams& h) {
  constexpr int kMaxCount = std::numeric_limits<std::uint16_t>::max();
  c.require(h.hit >= 1, "hit.hit", h.hit, "an integer >= 1");
  c.require(h.hit_max >= h.hit && h.hit_max <= kMaxCount, "hit.hit_max", h.hit_max,
            "an integer from hit.hit to " + std::to_string(kMaxCount));
  c.require(finite_non_negative(h.d_threshold), "hit.d_threshold", h.d_threshold,
            "a distance in metres, >= 0");
  c.require(finite_non_negative(h.d_duration), "hit.d_duration", h.d_duration,
            "a duration in seconds, >= 0");
}

void check_inflation(Checker& c, const InflationParams& f, double resolution) {
  c.require(finite_non_negative(f.inscribed_radius), "inflation.inscribed_radius",
            f.inscribed_radius, "a radius in metres, >= 0");
  c.require(std::isfinite(f.inflation_radius) && f.inflation_radius >= f.inscribed_radius,
            "inflation.inflation_radius", f.inflation_radius,
            "a radius in metres, >= inflation.inscribed_radius (" +
                model::format_number(f.inscribed_radius) + ")");
  const double reach = f.inflation_radius / resolution;  // cells; judged before any table
  if (finite_positive(resolution) && std::isfinite(f.inflation_radius))
    c.require(reach * reach <= kMaxInflationTable, "inflation.inflation_radius", f.inflation_radius,
              "a radius of at most " + model::format_number(std::sqrt(kMaxInflationTable), 4) +
                  " cells of " + model::format_number(resolution) +
                  " m (a few times the robot's radius, as nav2's examples use)");
  c.require(finite_non_negative(f.cost_scaling_factor), "inflation.cost_scaling_factor",
            f.cost_scaling_factor, "a decay rate in 1/m, >= 0");
}

}  // namespace

void check_costmap_params(const CostmapParams& params, const model::SourceLocation& where,
                          const std::string& prefix) {
  Checker checker{where, prefix, {}};
  check_window(checker, params);
  check_voxel(checker, params);
  check_hit(checker, params.hit);
  check_inflation(checker, params.inflation, params.resolution);
  checker.diagnostics.throw_if_errors();
}

}  // namespace rigdesign::costmap
