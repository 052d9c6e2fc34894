#include "rigdesign/metrics/tolerance_coverage.hpp"

#include <algorithm>
#include <limits>
#include <mutex>
#include <thread>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/section_polygons.hpp"
#include "rigdesign/model/parallel_for.hpp"
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

// One mount's region in one cross-section.
struct MountSection {
  std::vector<geometry::Polygon2> polygons;
  geometry::IntervalSet floor;
};

// SC complete and floor at one angle with the mounts whose entry in `moved` is set seeing that
// section instead of their nominal region (`moved` empty: every mount nominal).
std::pair<double, double> shares_at(const SectorAngle& angle,
                                    const std::vector<const MountSection*>& moved) {
  std::vector<std::vector<geometry::Polygon2>> regions;
  geometry::IntervalSet seen;
  for (std::size_t m = 0; m < angle.polygons.size(); ++m) {
    const MountSection* section = m < moved.size() ? moved[m] : nullptr;
    regions.push_back(section != nullptr ? section->polygons : angle.polygons[m]);
    seen = seen.united(section != nullptr ? section->floor : angle.floors[m]);
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

// A mount with a tolerance: its samples and each one's per-sector minima (complete, floor)
// with the other mounts nominal. Sections are not kept: 76 samples of six axes at 360 angles
// of four mounts would hold some 100 MB of polygons for the few the joint step reuses.
struct ToleratedMount {
  std::size_t index = 0;
  std::vector<PoseError> errors;
  std::vector<std::vector<std::pair<double, double>>> minima;  // per sample, per sector
};

// Mount `m` of the rig moved by `error` (its FOV at the narrowest when the error says so), cut
// at every angle; the other housings stay where the rig puts them.
std::vector<MountSection> moved_sections(const model::Rig& rig, std::size_t m,
                                         const PoseError& error,
                                         const model::SensorLibrary& library,
                                         const geometry::BodyOccluder& body,
                                         const std::vector<SectorAngle>& angles,
                                         const geometry::TessellationSettings& tessellation) {
  const model::Mount& mount = rig.mounts[m];
  const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
  const model::SensorMode narrowed = mode.narrowest();  // MountedFov keeps a pointer to it
  const geometry::MountedFov fov(error.narrowest_fov ? narrowed : mode,
                                 with_error(mount.T_robot_sensor, error), body, mount.housing_link,
                                 mount.limits, geometry::housings_around(rig, library, mount.id));
  std::vector<MountSection> sections;
  for (const SectorAngle& angle : angles)
    sections.push_back({geometry::section_polygons(fov, angle.frame, tessellation),
                        geometry::floor_coverage(fov, angle.frame)});
  return sections;
}

// The sample of `mount` with the smallest share of sector `s` (the first of equals).
std::size_t worst_sample(const ToleratedMount& mount, std::size_t s, bool floor) {
  std::size_t worst = 0;
  for (std::size_t i = 1; i < mount.minima.size(); ++i) {
    const auto share = [&](std::size_t k) {
      return floor ? mount.minima[k][s].second : mount.minima[k][s].first;
    };
    if (share(i) < share(worst)) worst = i;
  }
  return worst;
}

// The sectors' sampled azimuths, each with every nominal mount's region there (every mount
// placed once: a description's body makes each placement build a shadow).
std::vector<SectorAngle> sector_angles(const model::Rig& rig, const model::SensorLibrary& library,
                                       const geometry::BodyOccluder& body,
                                       const std::vector<model::SectorRequirement>& sectors,
                                       const CoverageSettings& settings) {
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
  return angles;
}

// Per sector, the shares' minima with mount `m` moved by `error` (the others nominal).
std::vector<std::pair<double, double>> minima_with_error(
    const model::Rig& rig, std::size_t m, const PoseError& error,
    const model::SensorLibrary& library, const geometry::BodyOccluder& body,
    const std::vector<model::SectorRequirement>& sectors, const std::vector<SectorAngle>& angles,
    const std::vector<std::pair<double, double>>& nominal_shares,
    const geometry::TessellationSettings& tessellation) {
  const std::vector<MountSection> sections =
      moved_sections(rig, m, error, library, body, angles, tessellation);
  std::vector<std::pair<double, double>> shares;
  std::vector<const MountSection*> replaced(rig.mounts.size(), nullptr);
  for (std::size_t a = 0; a < angles.size(); ++a) {
    // A section the mount misses whether moved or not keeps the nominal shares: most
    // angles of a camera's box, and the exact union is the cost of this loop.
    if (sections[a].polygons.empty() && sections[a].floor.empty() &&
        angles[a].polygons[m].empty() && angles[a].floors[m].empty()) {
      shares.push_back(nominal_shares[a]);
      continue;
    }
    replaced[m] = &sections[a];
    shares.push_back(shares_at(angles[a], replaced));
  }
  return sector_minima(sectors, angles, shares);
}

int worker_threads() {
  return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
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

std::vector<PoseError> mount_error_samples(const model::PoseTolerance& tolerance,
                                           const model::SensorMode& mode) {
  std::vector<PoseError> errors;
  if (tolerance.any()) errors = tolerance_samples(tolerance);
  if (!mode.fov_spread) return errors;
  if (errors.empty()) errors.emplace_back();  // the nominal pose at the narrowest FOV
  for (PoseError& error : errors) error.narrowest_fov = true;
  return errors;
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
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings,
    const WorkBudget* budget) {
  const bool any = std::any_of(rig.mounts.begin(), rig.mounts.end(), [&](const model::Mount& m) {
    const model::PoseTolerance* tolerance = rig.tolerance_for(m);
    return tolerance != nullptr &&
           !mount_error_samples(*tolerance, library.resolved_mode(m.sensor_id, m.mode_id)).empty();
  });
  if (!any || sectors.empty()) return {};
  const geometry::BodyOccluder body(rig.body);
  const std::vector<SectorAngle> angles = sector_angles(rig, library, body, sectors, settings);
  std::vector<std::pair<double, double>> nominal_shares;
  for (const SectorAngle& angle : angles) nominal_shares.push_back(shares_at(angle, {}));
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
  // One mount at a time, the others nominal: every (mount, sample) is a job of its own, run on
  // every core (CGAL's lazy exact kernel is thread-safe for objects no two threads share).
  std::vector<ToleratedMount> tolerated;
  std::vector<std::pair<std::size_t, std::size_t>> jobs;  // tolerated mount, sample
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::PoseTolerance* tolerance = rig.tolerance_for(rig.mounts[m]);
    if (tolerance == nullptr) continue;
    std::vector<PoseError> errors = mount_error_samples(
        *tolerance, library.resolved_mode(rig.mounts[m].sensor_id, rig.mounts[m].mode_id));
    if (errors.empty()) continue;
    tolerated.push_back({m, std::move(errors), {}});
    tolerated.back().minima.resize(tolerated.back().errors.size());
    for (std::size_t i = 0; i < tolerated.back().errors.size(); ++i)
      jobs.emplace_back(tolerated.size() - 1, i);
  }
  std::mutex progress_mutex;
  std::size_t done = 0;
  const double total = static_cast<double>(jobs.size());
  model::parallel_for(jobs.size(), worker_threads(), [&](std::size_t job) {
    if (budget) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      budget->check_time(static_cast<double>(done), total, "tolerance poses");
    }
    ToleratedMount& mount = tolerated[jobs[job].first];
    mount.minima[jobs[job].second] =
        minima_with_error(rig, mount.index, mount.errors[jobs[job].second], library, body, sectors,
                          angles, nominal_shares, settings.tessellation);
    if (budget) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      ++done;
      if (budget->progress) budget->progress(static_cast<double>(done), total);
    }
  });
  // In a fixed order, so that equal shares name the same error on every run.
  for (const ToleratedMount& mount : tolerated) {
    for (std::size_t i = 0; i < mount.errors.size(); ++i) {
      for (std::size_t s = 0; s < sectors.size(); ++s) {
        const std::vector<MountError> errors = {{rig.mounts[mount.index].id, mount.errors[i]}};
        const auto& [complete, floor] = mount.minima[i][s];
        if (complete < result[s].complete.share) result[s].complete = {complete, errors};
        if (floor < result[s].floor.share) result[s].floor = {floor, errors};
      }
    }
  }
  // Every mount at once at its own worst sample for the sector and share.
  if (tolerated.size() > 1) {
    for (std::size_t s = 0; s < sectors.size(); ++s) {
      for (const bool floor : {false, true}) {
        std::vector<MountError> errors;
        std::vector<std::pair<std::size_t, std::vector<MountSection>>> chosen;  // mount, cuts
        for (const ToleratedMount& mount : tolerated) {
          const std::size_t worst = worst_sample(mount, s, floor);
          const double share = floor ? mount.minima[worst][s].second : mount.minima[worst][s].first;
          if (share >= (floor ? nominal[s].second : nominal[s].first)) continue;  // no worse
          errors.push_back({rig.mounts[mount.index].id, mount.errors[worst]});
          chosen.emplace_back(mount.index,
                              moved_sections(rig, mount.index, mount.errors[worst], library, body,
                                             angles, settings.tessellation));
        }
        if (chosen.size() < 2) continue;  // one mount's worst is already recorded
        std::vector<std::pair<double, double>> shares;
        std::vector<const MountSection*> replaced(rig.mounts.size(), nullptr);
        for (std::size_t a = 0; a < angles.size(); ++a) {
          for (const auto& [index, sections] : chosen) replaced[index] = &sections[a];
          shares.push_back(shares_at(angles[a], replaced));
        }
        const std::pair<double, double> joint = sector_minima(sectors, angles, shares)[s];
        WorstShare& worst = floor ? result[s].floor : result[s].complete;
        const double share = floor ? joint.second : joint.first;
        if (share < worst.share) worst = {share, errors};
      }
    }
  }
  for (SectorTolerance& sector : result) {
    sector.pass = sector.complete.share >= sector.sector.min_complete_coverage &&
                  sector.floor.share >= sector.sector.min_floor_coverage;
  }
  return result;
}

std::vector<ErrorSweep> tolerance_sweeps(const model::Rig& rig, const model::SensorLibrary& library,
                                         const std::vector<model::SectorRequirement>& sectors,
                                         const CoverageSettings& settings, int steps) {
  std::vector<ErrorSweep> sweeps;
  std::vector<std::size_t> mount_of;  // per sweep
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::PoseTolerance* tolerance = rig.tolerance_for(rig.mounts[m]);
    if (tolerance == nullptr) continue;
    for (const int axis : {1, 2}) {
      const double width = tolerance->rpy[axis];
      if (width <= 0) continue;
      ErrorSweep sweep;
      sweep.mount_id = rig.mounts[m].id;
      sweep.axis = axis;
      sweep.half_width = width;
      for (int i = 0; i < steps; ++i)
        sweep.errors.push_back(-3 * width + 6 * width * i / std::max(1, steps - 1));
      sweeps.push_back(std::move(sweep));
      mount_of.push_back(m);
    }
  }
  if (sweeps.empty() || sectors.empty()) return {};
  const geometry::BodyOccluder body(rig.body);
  const std::vector<SectorAngle> angles = sector_angles(rig, library, body, sectors, settings);
  std::vector<std::pair<double, double>> nominal_shares;
  for (const SectorAngle& angle : angles) nominal_shares.push_back(shares_at(angle, {}));
  const std::size_t per_sweep = static_cast<std::size_t>(steps);
  std::vector<std::vector<std::pair<double, double>>> minima(sweeps.size() * per_sweep);
  model::parallel_for(minima.size(), worker_threads(), [&](std::size_t job) {
    const ErrorSweep& sweep = sweeps[job / per_sweep];
    PoseError error;
    error.rpy[sweep.axis] = sweep.errors[job % per_sweep];
    minima[job] = minima_with_error(rig, mount_of[job / per_sweep], error, library, body, sectors,
                                    angles, nominal_shares, settings.tessellation);
  });
  for (std::size_t k = 0; k < sweeps.size(); ++k) {
    ErrorSweep& sweep = sweeps[k];
    for (const model::SectorRequirement& sector : sectors)
      sweep.sectors.push_back({sector.name, {}});
    for (std::size_t i = 0; i < per_sweep; ++i) {
      double smallest = std::numeric_limits<double>::infinity();
      for (std::size_t s = 0; s < sectors.size(); ++s) {
        const auto& [complete, floor] = minima[k * per_sweep + i][s];
        const double margin = std::min(complete - sectors[s].min_complete_coverage,
                                       floor - sectors[s].min_floor_coverage);
        sweep.sectors[s].second.push_back(margin);
        smallest = std::min(smallest, margin);
      }
      sweep.smallest.push_back(smallest);
    }
  }
  return sweeps;
}

double SectorTolerance::margin() const {
  return std::min(complete.share - sector.min_complete_coverage,
                  floor.share - sector.min_floor_coverage);
}

bool SectorTolerance::floor_binds() const {
  return floor.share - sector.min_floor_coverage < complete.share - sector.min_complete_coverage;
}

}  // namespace rigdesign::metrics
