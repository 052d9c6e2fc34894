#include "rigdesign/select/pose_refinement.hpp"

#include <algorithm>
#include <limits>

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/model/rotation.hpp"
#include "select/search_rules.hpp"

namespace rigdesign::select {
namespace {

constexpr double kUnboundedMargin = std::numeric_limits<double>::infinity();
// The compass search halves its steps from half a grid step down to 1/32 of one, and stops
// after kMaxRefinementRigs at the latest.
constexpr int kHalvings = 5;
constexpr int kMaxEvaluations = kMaxRefinementRigs;
// A move must widen the margin by more than rounding.
constexpr double kImprovement = 1e-12;

// A sector's thresholds at the problem angles it holds (indices into the local angles).
struct LocalSector {
  std::vector<std::size_t> angles;
  double min_complete = 0.0;
  double min_floor = 0.0;
};

}  // namespace

struct RasterMargins::State {
  const SelectionSpace& space;
  geometry::BodyOccluder body;
  std::vector<geometry::SectionFrame> frames;  // at the local angles
  std::vector<geometry::RasterGrid> grids;
  std::vector<LocalSector> sectors;
  std::vector<LocalSector> robust_sectors;
  bool single_failure = false;
  std::vector<bool> fails_in_condition;  // per mount, when a condition is to be survived
  std::vector<const model::SensorMode*> modes;
  std::vector<std::string> housings;  // per mount: its housing link (model::Mount's)
  std::vector<std::vector<geometry::SectionRaster>> rasters;  // per mount, per local angle

  State(const SelectionSpace& s, const model::Rig& rig) : space(s), body(rig.body) {}

  std::vector<geometry::SectionRaster> rasterise(std::size_t mount,
                                                 const model::Pose3& pose) const {
    const geometry::MountedFov fov(*modes[mount], pose, body, housings[mount]);
    std::vector<geometry::SectionRaster> out;
    for (std::size_t i = 0; i < frames.size(); ++i)
      out.push_back(geometry::rasterize(fov, frames[i], grids[i]));
    return out;
  }

  // Per sector of `over`, the smallest margin of the union of the mounts `kept` says.
  template <typename Kept>
  void margins_of(const std::vector<LocalSector>& over, Kept kept,
                  const std::vector<geometry::SectionRaster>* replaced, std::size_t at,
                  std::vector<double>& out) const {
    for (const LocalSector& sector : over) {
      double margin = kUnboundedMargin;
      for (const std::size_t i : sector.angles) {
        geometry::SectionRaster seen(grids[i]);
        for (std::size_t m = 0; m < rasters.size(); ++m) {
          if (!kept(m)) continue;
          seen |= (m == at && replaced != nullptr) ? (*replaced)[i] : rasters[m][i];
        }
        margin = std::min({margin, seen.complete_share() - sector.min_complete,
                           seen.floor_share() - sector.min_floor});
      }
      out.push_back(margin);
    }
  }

  // Every sector's margin, and every robustness sector's after each failure to survive,
  // smallest first: the refinement compares these lexicographically (leximin), so a move
  // that widens the left sector's margin counts while the right's, equally small, waits
  // for its own move.
  std::vector<double> margins(const std::vector<geometry::SectionRaster>* replaced,
                              std::size_t at) const {
    std::vector<double> out;
    margins_of(
        sectors, [](std::size_t) { return true; }, replaced, at, out);
    if (single_failure) {
      for (std::size_t j = 0; j < rasters.size(); ++j)
        margins_of(
            robust_sectors, [&](std::size_t m) { return m != j; }, replaced, at, out);
    }
    if (!fails_in_condition.empty()) {
      margins_of(
          robust_sectors, [&](std::size_t m) { return !fails_in_condition[m]; }, replaced, at, out);
    }
    std::sort(out.begin(), out.end());
    return out;
  }
};

RasterMargins::RasterMargins(const SelectionSpace& space, const SatisficingTargets& targets,
                             const model::Rig& rig)
    : state_(std::make_unique<State>(space, rig)) {
  State& s = *state_;
  // Local angles: the problem's angles inside some sector, on the search's own frames.
  std::vector<std::size_t> local_of(space.grids().size(), space.grids().size());
  const auto local_sectors = [&](const std::vector<model::SectorRequirement>& requirements) {
    std::vector<LocalSector> out;
    for (const model::SectorRequirement& sector : requirements) {
      LocalSector local{{}, sector.min_complete_coverage, sector.min_floor_coverage};
      for (std::size_t a = 0; a < space.grids().size(); ++a) {
        if (!metrics::in_sector(sector, space.angle(a))) continue;
        if (local_of[a] == space.grids().size()) {
          local_of[a] = s.frames.size();
          s.frames.push_back(geometry::section_frame(s.body, space.angle(a),
                                                     space.catalog().distance_of_interest));
          s.grids.push_back(space.grids()[a]);
        }
        local.angles.push_back(local_of[a]);
      }
      out.push_back(std::move(local));
    }
    return out;
  };
  s.sectors = local_sectors(targets.sectors);
  if (targets.robustness && targets.robustness->any()) {
    s.robust_sectors = local_sectors(robust_sectors(targets));
    s.single_failure = targets.robustness->single_failure;
  }
  for (const model::Mount& mount : rig.mounts) {
    s.modes.push_back(&space.library().resolved_mode(mount.sensor_id, mount.mode_id));
    s.housings.push_back(mount.housing_link);
    if (targets.robustness && targets.robustness->condition)
      s.fails_in_condition.push_back(
          !s.modes.back()->light.immune_to(*targets.robustness->condition));
  }
  for (std::size_t m = 0; m < rig.mounts.size(); ++m)
    s.rasters.push_back(s.rasterise(m, rig.mounts[m].T_robot_sensor));
}

RasterMargins::~RasterMargins() = default;

std::vector<double> RasterMargins::margins_with(std::size_t mount, const model::Pose3& pose) {
  const std::vector<geometry::SectionRaster> moved = state_->rasterise(mount, pose);
  return state_->margins(&moved, mount);
}

std::vector<double> RasterMargins::margins() {
  return state_->margins(nullptr, 0);
}

std::vector<double> RasterMargins::sector_margins_with(std::size_t mount,
                                                       const model::Pose3& pose) {
  const std::vector<geometry::SectionRaster> moved = state_->rasterise(mount, pose);
  std::vector<double> out;
  state_->margins_of(
      state_->sectors, [](std::size_t) { return true; }, &moved, mount, out);
  return out;
}

namespace {

double smallest(const std::vector<double>& margins) {
  return margins.empty() ? kUnboundedMargin : margins.front();
}

bool wider(const std::vector<double>& candidate, const std::vector<double>& incumbent) {
  for (std::size_t i = 0; i < candidate.size() && i < incumbent.size(); ++i) {
    if (candidate[i] > incumbent[i] + kImprovement) return true;
    if (candidate[i] < incumbent[i] - kImprovement) return false;
  }
  return false;
}

}  // namespace

void RasterMargins::move(std::size_t mount, const model::Pose3& pose) {
  state_->rasters[mount] = state_->rasterise(mount, pose);
}

bool RasterMargins::inside_body(const model::Pose3& pose) const {
  return state_->body.contains(pose.translation());
}

model::Pose3 pose_from_values(const std::array<double, 6>& values) {
  return model::pose_from_xyz_rpy(model::Vec3(values[0], values[1], values[2]),
                                  model::Vec3(values[3], values[4], values[5]));
}

std::vector<MarginSample> margin_sweep(const SelectionSpace& space,
                                       const SatisficingTargets& targets, const model::Rig& rig,
                                       std::size_t mount, const std::array<double, 6>& values,
                                       const model::PoseAxisRange& range, int samples) {
  RasterMargins margins(space, targets, rig);
  std::vector<MarginSample> curve;
  for (int i = 0; i < samples; ++i) {
    std::array<double, 6> at = values;
    at[range.axis] =
        samples < 2 ? range.low : range.low + (range.high - range.low) * i / (samples - 1);
    const model::Pose3 pose = pose_from_values(at);
    if (margins.inside_body(pose)) continue;
    curve.push_back({at[range.axis], smallest(margins.margins_with(mount, pose)),
                     margins.sector_margins_with(mount, pose)});
  }
  return curve;
}

PoseRefinement refine_poses(const SelectionSpace& space, const Selection& selection,
                            const SatisficingTargets& targets, const ProgressSink& progress) {
  PoseRefinement refinement;
  refinement.rig = selection.rig;
  // The axes to move: every varied axis of every chosen slot with a pose range.
  struct Parameter {
    std::size_t mount;
    int axis;
    double low, high, step;
  };
  std::vector<Parameter> parameters;
  std::vector<std::array<double, 6>> values;
  for (std::size_t m = 0; m < selection.chosen.size(); ++m) {
    const CatalogOption& option = *selection.chosen[m];
    const model::MountingSlot& slot = space.catalog().slots[option.slot];
    values.push_back(slot.poses[option.pose].values);
    for (const model::PoseAxisRange& range : slot.ranges)
      parameters.push_back({m, range.axis, range.low, range.high, range.step});
  }
  if (parameters.empty()) return refinement;
  refinement.tried = true;
  refinement.counts_failures = targets.robustness && targets.robustness->any();

  RasterMargins margins(space, targets, selection.rig);
  std::vector<double> best = margins.margins();
  refinement.grid_margin = smallest(best);
  std::vector<double> steps;
  for (const Parameter& p : parameters) steps.push_back(p.step / 2);
  for (int halving = 0; halving < kHalvings && refinement.evaluations < kMaxEvaluations;) {
    bool moved = false;
    for (std::size_t i = 0; i < parameters.size() && refinement.evaluations < kMaxEvaluations;
         ++i) {
      const Parameter& p = parameters[i];
      for (const double direction : {1.0, -1.0}) {
        std::array<double, 6> trial = values[p.mount];
        trial[p.axis] = std::clamp(trial[p.axis] + direction * steps[i], p.low, p.high);
        if (trial[p.axis] == values[p.mount][p.axis]) continue;
        const model::Pose3 pose = pose_from_values(trial);
        if (margins.inside_body(pose)) continue;
        ++refinement.evaluations;
        if (progress)
          progress({"pose refinement", static_cast<double>(refinement.evaluations),
                    static_cast<double>(kMaxEvaluations), "rigs (at most)", ""});
        std::vector<double> margin = margins.margins_with(p.mount, pose);
        if (wider(margin, best)) {
          best = std::move(margin);
          values[p.mount] = trial;
          margins.move(p.mount, pose);
          moved = true;
          break;
        }
      }
    }
    if (!moved) {
      for (double& step : steps) step /= 2;
      ++halving;
    }
  }
  refinement.refined_margin = smallest(best);
  refinement.values = values;
  for (const Parameter& p : parameters) {
    const CatalogOption& option = *selection.chosen[p.mount];
    const double grid = space.catalog().slots[option.slot].poses[option.pose].values[p.axis];
    refinement.axes.push_back(
        {selection.rig.mounts[p.mount].id, p.axis, p.low, p.high, grid, values[p.mount][p.axis]});
  }
  // Unmoved, the grid poses are the best seen.
  if (std::all_of(refinement.axes.begin(), refinement.axes.end(),
                  [](const RefinedAxis& axis) { return axis.refined == axis.grid; }))
    return refinement;

  for (std::size_t m = 0; m < values.size(); ++m) {
    if (!space.catalog().slots[selection.chosen[m]->slot].ranges.empty())
      refinement.rig.mounts[m].T_robot_sensor = pose_from_values(values[m]);
  }
  metrics::CoverageSettings exact = space.settings();
  exact.exact = true;
  if (progress) progress({"exact verification of the refined poses", 0, 1, "rigs", ""});
  refinement.coverage =
      metrics::compute_coverage(refinement.rig, space.library(), targets.sectors, exact);
  refinement.accepted =
      std::all_of(refinement.coverage.sectors.begin(), refinement.coverage.sectors.end(),
                  [](const metrics::SectorCoverage& sector) { return sector.pass; });
  if (refinement.accepted && targets.robustness && targets.robustness->any()) {
    refinement.failures =
        failure_impacts(refinement.rig, space, targets, exact, [&](double done, double total) {
          if (progress)
            progress({"exact verification of the refined poses' failures", done, total,
                      "sector angles", ""});
        });
    refinement.accepted =
        std::all_of(refinement.failures.begin(), refinement.failures.end(),
                    [](const FailureImpact& failure) { return failure.broken_sectors.empty(); });
  }
  return refinement;
}

}  // namespace rigdesign::select
