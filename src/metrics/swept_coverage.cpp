#include "rigdesign/metrics/swept_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include "coverage_parts.hpp"
#include "rigdesign/geometry/section_polygons.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::metrics {
namespace {

constexpr double kSweepFullTurn = 2 * std::numbers::pi;

// The rho intervals of one section where some mount sees part of the column: each mount's
// section polygons projected on rho (a polygon is connected, so its shadow on rho is one
// interval), united.
geometry::IntervalSet sweep_seen_columns(const std::vector<detail::PlacedMount>& mounts,
                                         const geometry::SectionFrame& frame,
                                         const geometry::TessellationSettings& tessellation) {
  std::vector<geometry::IntervalSet::Interval> spans;
  for (const detail::PlacedMount& mount : mounts) {
    if (!mount.fov.may_reach_azimuth(frame.theta)) continue;
    for (const geometry::Polygon2& polygon :
         geometry::section_polygons(mount.fov, frame, tessellation)) {
      if (polygon.empty()) continue;
      double low = polygon.front().x(), high = low;
      for (const model::Vec2& vertex : polygon) {
        low = std::min(low, vertex.x());
        high = std::max(high, vertex.x());
      }
      spans.emplace_back(low, high);
    }
  }
  std::sort(spans.begin(), spans.end());
  geometry::IntervalSet seen;
  for (const auto& [low, high] : spans) seen.append(low, high);
  return seen;
}

void sweep_require(bool ok, const std::string& field, double value, const std::string& expected) {
  if (!ok) {
    throw model::InputError(
        model::Diagnostic{{}, field, "is " + model::format_number(value), expected});
  }
}

void sweep_check_input(const SweepMotion& motion, const SweepSettings& settings) {
  const auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  if (motion.kind == SweepKind::rotate) {
    sweep_require(std::isfinite(motion.turn_rate) && motion.turn_rate != 0.0, "sweep.turn_rate",
                  motion.turn_rate, "a turn rate other than 0 [rad/s]");
  } else {
    sweep_require(std::isfinite(motion.arc_radius) && motion.arc_radius != 0.0, "sweep.arc_radius",
                  motion.arc_radius, "a radius other than 0 [m]");
    sweep_require(positive(motion.speed), "sweep.speed", motion.speed, "a speed > 0 [m/s]");
  }
  sweep_require(positive(settings.horizon), "sweep.horizon", settings.horizon, "a time > 0 [s]");
  sweep_require(positive(settings.cell), "sweep.cell", settings.cell, "a cell side > 0 [m]");
  sweep_require(positive(settings.deceleration), "sweep.deceleration", settings.deceleration,
                "a deceleration > 0 [m/s^2]");
}

// The largest time step at which no cell within `reach` of the robot's axis moves half a cell
// relative to the robot (its speed there is at most v + |omega| reach) and the robot turns
// less than half the azimuth step, shortened to divide the horizon into whole steps. The
// count stays a double: it is judged against the sample cap before it becomes an integer
// (a spin at 1e20 rad/s needs 1e23 steps, which no integer type holds).
std::pair<double, double> sweep_time_step(const SweepMotion& motion, double reach,
                                          double azimuth_step, const SweepSettings& settings) {
  const double omega = std::abs(motion.angular_rate());
  double step = settings.cell / (2.0 * (motion.linear_speed() + omega * reach));
  step = std::min(step, azimuth_step / (2.0 * omega));
  const double count = std::max(1.0, std::ceil(settings.horizon / step));
  return {settings.horizon / count, count};
}

// Cells on the grid's square around the axis, judged before the grid is built.
double sweep_grid_bound(double distance, double cell) {
  const double side = 2.0 * std::ceil(distance / cell) + 1.0;
  return side * side;
}

// Cells centred on multiples of `cell` within `distance` of the axis and outside the body.
// Precondition: sweep_grid_bound(distance, cell) was judged against the sample cap.
std::vector<SweepCell> sweep_grid(const VisibilityMap& map, double distance, double cell) {
  const long half = static_cast<long>(std::ceil(distance / cell));
  std::vector<SweepCell> cells;
  for (long j = -half; j <= half; ++j) {
    for (long i = -half; i <= half; ++i) {
      const model::Vec2 centre(static_cast<double>(i) * cell, static_cast<double>(j) * cell);
      const double rho = centre.norm();
      if (rho > distance || rho <= map.body_radius(std::atan2(centre.y(), centre.x()))) continue;
      SweepCell swept;
      swept.centre = centre;
      cells.push_back(swept);
    }
  }
  return cells;
}

// Samples the motion: each cell's first sight, and the first time the body's outline comes
// within half a cell of its centre (cells it touches at t = 0 are against the body already).
void sweep_sample(const VisibilityMap& map, const SweepMotion& motion, double time_step, long steps,
                  double half_cell, std::vector<SweepCell>& cells) {
  std::vector<bool> touching(cells.size(), false);
  std::vector<std::size_t> open(cells.size());
  for (std::size_t i = 0; i < open.size(); ++i) open[i] = i;
  for (long k = 0; k <= steps && !open.empty(); ++k) {
    const double t = static_cast<double>(k) * time_step;
    const SweepPose pose = motion.pose_at(t);
    const double c = std::cos(pose.heading), s = std::sin(pose.heading);
    const auto done = [&](std::size_t i) {
      SweepCell& cell = cells[i];
      const model::Vec2 offset = cell.centre - pose.position;
      const model::Vec2 p_robot(c * offset.x() + s * offset.y(), -s * offset.x() + c * offset.y());
      const double rho = p_robot.norm();
      const double theta = std::atan2(p_robot.y(), p_robot.x());
      if (!cell.first_seen && map.sees(rho, theta)) cell.first_seen = t;
      const bool touches = rho - half_cell <= map.body_radius(theta);
      if (k == 0) touching[i] = touches;
      if (k > 0 && !touching[i] && !cell.reached && touches) cell.reached = t;
      return cell.first_seen && (cell.reached || touching[i]);
    };
    open.erase(std::remove_if(open.begin(), open.end(), done), open.end());
  }
}

// Seen share, all-seen time and the check's counts from the cells' times.
void sweep_summarize(SweepRun& run, double stopping_time) {
  std::size_t seen = 0;
  double last_seen = 0.0;
  double least_warning = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < run.cells.size(); ++i) {
    SweepCell& cell = run.cells[i];
    if (cell.first_seen) {
      ++seen;
      last_seen = std::max(last_seen, *cell.first_seen);
    }
    if (!cell.reached) continue;
    ++run.swept;
    if (*cell.reached < stopping_time) {
      ++run.reached_too_soon;
      continue;
    }
    cell.late = !cell.first_seen || *cell.first_seen > *cell.reached - stopping_time;
    if (!cell.late) continue;
    ++run.late;
    // Never seen warns least; among equals the one reached first is the worse.
    const double warning = cell.first_seen ? *cell.reached - *cell.first_seen
                                           : -std::numeric_limits<double>::infinity();
    if (!run.worst_late || warning < least_warning ||
        (warning == least_warning && *cell.reached < *run.cells[*run.worst_late].reached)) {
      least_warning = warning;
      run.worst_late = i;
    }
  }
  run.seen_share =
      run.cells.empty() ? 1.0 : static_cast<double>(seen) / static_cast<double>(run.cells.size());
  if (seen == run.cells.size()) run.all_seen_time = last_seen;
}

// The order of badness: more late cells, then a cell never seen, a later all-seen time, a
// smaller seen share.
auto sweep_badness(const SweepRun& run) {
  return std::make_tuple(run.late, !run.all_seen_time, run.all_seen_time.value_or(0.0),
                         -run.seen_share);
}

}  // namespace

VisibilityMap::VisibilityMap(const model::Rig& rig, const model::SensorLibrary& library,
                             double distance, const CoverageSettings& settings)
    : distance_(distance) {
  const geometry::BodyOccluder body(rig.body);
  std::vector<detail::PlacedMount> mounts;
  for (const model::Mount& mount : rig.mounts)
    mounts.push_back(detail::place_mount(rig, mount, library, body));
  const std::vector<double> thetas = detail::sampled_azimuths(settings);
  step_ = kSweepFullTurn / static_cast<double>(thetas.size());
  for (const double theta : thetas) {
    const geometry::SectionFrame frame = geometry::section_frame(body, theta, distance);
    body_radius_.push_back(frame.r);
    seen_.push_back(frame.width() > 0 && frame.h > 0
                        ? sweep_seen_columns(mounts, frame, settings.tessellation)
                        : geometry::IntervalSet{});
  }
}

std::size_t VisibilityMap::index_of(double theta) const {
  const long count = static_cast<long>(seen_.size());
  long index = std::lround(theta / step_) % count;
  if (index < 0) index += count;
  return static_cast<std::size_t>(index);
}

double SweepMotion::angular_rate() const {
  return kind == SweepKind::rotate ? turn_rate : speed / arc_radius;
}

SweepPose SweepMotion::pose_at(double t) const {
  SweepPose pose;
  pose.heading = angular_rate() * t;
  if (kind == SweepKind::arc) {
    // On the circle about (0, R): the centre stays R from it, heading along the tangent.
    pose.position = model::Vec2(arc_radius * std::sin(pose.heading),
                                arc_radius * (1.0 - std::cos(pose.heading)));
  }
  return pose;
}

double rim_turn_rate(double speed, const model::RobotBody& body) {
  return speed / body.radius;
}

double default_horizon(const SweepMotion& motion, double distance) {
  return motion.kind == SweepKind::rotate ? kSweepFullTurn / std::abs(motion.turn_rate)
                                          : distance / motion.speed;
}

SweptCoverage swept_coverage(const model::Rig& rig, const model::SensorLibrary& library,
                             const SweepMotion& motion, const SweepSettings& settings) {
  sweep_check_input(motion, settings);
  SweptCoverage result;
  result.distance = rig.distance_of_interest;
  result.cell = settings.cell;
  result.horizon = settings.horizon;
  // An arc carries the robot up to min(v T, 2 |R|) from the start: the map reaches every
  // grid cell from wherever the robot is.
  const double travel = motion.kind == SweepKind::arc ? std::min(motion.speed * settings.horizon,
                                                                 2.0 * std::abs(motion.arc_radius))
                                                      : 0.0;
  const VisibilityMap map(rig, library, result.distance + travel, settings.coverage);
  result.azimuth_step = map.azimuth_step();
  for (std::size_t a = 0; a < map.azimuth_count(); ++a) {
    const double theta = static_cast<double>(a) * map.azimuth_step();
    result.body_outline.push_back(map.body_radius(theta) *
                                  model::Vec2(std::cos(theta), std::sin(theta)));
  }
  const double fastest_body_point =
      motion.kind == SweepKind::arc ? motion.speed : std::abs(motion.turn_rate) * rig.body.radius;
  result.stopping_time = fastest_body_point / settings.deceleration;
  const auto [time_step, steps] =
      sweep_time_step(motion, map.distance(), map.azimuth_step(), settings);
  result.time_step = time_step;

  std::vector<SweepMotion> motions = {motion};
  if (motion.kind == SweepKind::rotate) {
    motions = {motion, motion};
    motions[0].turn_rate = std::abs(motion.turn_rate);
    motions[1].turn_rate = -std::abs(motion.turn_rate);
  }
  const auto refuse_over_cap = [&](double cells, double times) {
    const double samples = cells * times * static_cast<double>(motions.size());
    if (samples <= kMaxSweepSamples) return;
    throw model::InputError(
        model::Diagnostic{{},
                          "sweep",
                          "needs " + model::format_number(samples, 3) + " cell samples (" +
                              model::format_number(cells, 3) + " cells, " +
                              model::format_number(times, 3) + " times)",
                          "at most " + model::format_number(kMaxSweepSamples, 3) +
                              ": a shorter time, a slower turn or larger cells"});
  };
  // The grid's square alone, before it is allocated; then the cells and times the run samples.
  refuse_over_cap(sweep_grid_bound(result.distance, settings.cell), 1.0);
  const std::vector<SweepCell> grid = sweep_grid(map, result.distance, settings.cell);
  refuse_over_cap(static_cast<double>(grid.size()), steps + 1.0);
  for (const SweepMotion& run_motion : motions) {
    SweepRun run;
    run.motion = run_motion;
    run.cells = grid;
    sweep_sample(map, run_motion, time_step, static_cast<long>(steps), settings.cell / 2.0,
                 run.cells);
    sweep_summarize(run, result.stopping_time);
    result.runs.push_back(std::move(run));
  }
  for (std::size_t r = 1; r < result.runs.size(); ++r) {
    if (sweep_badness(result.runs[r]) > sweep_badness(result.runs[result.worst])) result.worst = r;
  }
  return result;
}

}  // namespace rigdesign::metrics
