#include "rigdesign/metrics/tolerance_coverage.hpp"

#include <algorithm>
#include <limits>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/section_polygons.hpp"
#include "rigdesign/model/rotation.hpp"

namespace rigdesign::metrics {
namespace {

// One sampled azimuth of the sectors: its section and each mount's nominal region there.
struct SectorAngle {
  double theta = 0.0;
  geometry::SectionFrame frame;
  std::vector<std::vector<geometry::Polygon2>> polygons;  // per mount
  std::vector<geometry::IntervalSet> floors;              // per mount
};

// SC complete and floor at one angle with mount `replaced` seeing `polygons` and `floor`
// instead of its nominal region (no replacement when `replaced` is past the last mount).
std::pair<double, double> shares_at(const SectorAngle& angle, std::size_t replaced,
                                    const std::vector<geometry::Polygon2>& polygons,
                                    const geometry::IntervalSet& floor) {
  std::vector<std::vector<geometry::Polygon2>> regions;
  geometry::IntervalSet seen;
  for (std::size_t m = 0; m < angle.polygons.size(); ++m) {
    regions.push_back(m == replaced ? polygons : angle.polygons[m]);
    seen = seen.united(m == replaced ? floor : angle.floors[m]);
  }
  return {geometry::union_area(regions) / angle.frame.area(), seen.length() / angle.frame.width()};
}

// Per sector, the smallest SC complete and floor over its angles, given each angle's shares.
std::vector<std::pair<double, double>> sector_minima(
    const std::vector<model::SectorRequirement>& sectors, const std::vector<SectorAngle>& angles,
    const std::vector<std::pair<double, double>>& shares) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, double>> minima(sectors.size(), {kNone, kNone});
  for (std::size_t a = 0; a < angles.size(); ++a) {
    for (std::size_t s = 0; s < sectors.size(); ++s) {
      if (!in_sector(sectors[s], angles[a].theta)) continue;
      minima[s].first = std::min(minima[s].first, shares[a].first);
      minima[s].second = std::min(minima[s].second, shares[a].second);
    }
  }
  // A sector no sampled angle falls in sees nothing, as in compute_coverage.
  for (auto& [complete, floor] : minima) {
    complete = complete == kNone ? 0.0 : judged_share(complete);
    floor = floor == kNone ? 0.0 : judged_share(floor);
  }
  return minima;
}

}  // namespace

std::vector<PoseError> tolerance_samples(const model::PoseTolerance& tolerance) {
  std::vector<double> widths = {tolerance.xyz.x(), tolerance.xyz.y(), tolerance.xyz.z(),
                                tolerance.rpy.x(), tolerance.rpy.y(), tolerance.rpy.z()};
  std::vector<std::size_t> axes;
  for (std::size_t i = 0; i < widths.size(); ++i)
    if (widths[i] > 0) axes.push_back(i);
  const auto error_of = [](const std::vector<double>& values) {
    PoseError error;
    error.xyz = model::Vec3(values[0], values[1], values[2]);
    error.rpy = model::Vec3(values[3], values[4], values[5]);
    return error;
  };
  std::vector<PoseError> samples;
  for (std::size_t corner = 0; corner < (std::size_t{1} << axes.size()); ++corner) {
    std::vector<double> values(6, 0.0);
    for (std::size_t k = 0; k < axes.size(); ++k)
      values[axes[k]] = (corner >> k & 1U) ? widths[axes[k]] : -widths[axes[k]];
    samples.push_back(error_of(values));
  }
  if (axes.size() > 1) {
    for (const std::size_t axis : axes) {
      for (const double sign : {-1.0, 1.0}) {
        std::vector<double> values(6, 0.0);
        values[axis] = sign * widths[axis];
        samples.push_back(error_of(values));
      }
    }
  }
  return samples;
}

model::Pose3 with_error(const model::Pose3& nominal, const PoseError& error) {
  model::Pose3 moved = nominal;
  moved.linear() =
      nominal.linear() * model::rotation_from_rpy(error.rpy.x(), error.rpy.y(), error.rpy.z());
  moved.translation() += error.xyz;
  return moved;
}

std::vector<SectorTolerance> tolerance_coverage(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings) {
  const bool any = std::any_of(rig.mounts.begin(), rig.mounts.end(), [&](const model::Mount& m) {
    const model::PoseTolerance* tolerance = rig.tolerance_for(m);
    return tolerance != nullptr && tolerance->any();
  });
  if (!any || sectors.empty()) return {};
  const geometry::BodyOccluder body(rig.body);
  // Every mount placed once (a description's body makes each placement build a shadow).
  std::vector<detail::PlacedMount> nominal_mounts;
  for (const model::Mount& mount : rig.mounts)
    nominal_mounts.push_back(detail::place_mount(rig, mount, library, body));
  std::vector<SectorAngle> angles;
  for (const double theta : detail::sampled_azimuths(settings)) {
    if (std::none_of(sectors.begin(), sectors.end(),
                     [&](const model::SectorRequirement& s) { return in_sector(s, theta); }))
      continue;
    SectorAngle angle;
    angle.theta = theta;
    angle.frame = geometry::section_frame(body, theta, rig.distance_of_interest);
    for (const detail::PlacedMount& placed : nominal_mounts) {
      angle.polygons.push_back(
          geometry::section_polygons(placed.fov, angle.frame, settings.tessellation));
      angle.floors.push_back(geometry::floor_coverage(placed.fov, angle.frame));
    }
    angles.push_back(std::move(angle));
  }
  std::vector<std::pair<double, double>> nominal_shares;
  for (const SectorAngle& angle : angles)
    nominal_shares.push_back(shares_at(angle, rig.mounts.size(), {}, {}));
  const std::vector<std::pair<double, double>> nominal =
      sector_minima(sectors, angles, nominal_shares);

  std::vector<SectorTolerance> result;
  for (std::size_t s = 0; s < sectors.size(); ++s) {
    SectorTolerance sector;
    sector.sector = sectors[s];
    sector.nominal_complete = nominal[s].first;
    sector.nominal_floor = nominal[s].second;
    sector.complete.share = nominal[s].first;
    sector.floor.share = nominal[s].second;
    result.push_back(sector);
  }
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::PoseTolerance* tolerance = rig.tolerance_for(rig.mounts[m]);
    if (tolerance == nullptr || !tolerance->any()) continue;
    for (const PoseError& error : tolerance_samples(*tolerance)) {
      model::Mount moved = rig.mounts[m];
      moved.T_robot_sensor = with_error(moved.T_robot_sensor, error);
      const detail::PlacedMount placed = detail::place_mount(rig, moved, library, body);
      std::vector<std::pair<double, double>> shares;
      for (const SectorAngle& angle : angles) {
        shares.push_back(shares_at(
            angle, m, geometry::section_polygons(placed.fov, angle.frame, settings.tessellation),
            geometry::floor_coverage(placed.fov, angle.frame)));
      }
      const std::vector<std::pair<double, double>> minima = sector_minima(sectors, angles, shares);
      for (std::size_t s = 0; s < sectors.size(); ++s) {
        if (minima[s].first < result[s].complete.share)
          result[s].complete = {minima[s].first, moved.id, error};
        if (minima[s].second < result[s].floor.share)
          result[s].floor = {minima[s].second, moved.id, error};
      }
    }
  }
  for (SectorTolerance& sector : result) {
    sector.pass = sector.complete.share >= sector.sector.min_complete_coverage &&
                  sector.floor.share >= sector.sector.min_floor_coverage;
  }
  return result;
}

}  // namespace rigdesign::metrics
