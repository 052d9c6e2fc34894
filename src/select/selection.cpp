#include "rigdesign/select/selection.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <optional>
#include <thread>

#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/housing_clearance.hpp"
#include "rigdesign/geometry/mount_placement.hpp"
#include "rigdesign/metrics/failure_coverage.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/parallel_for.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/select/pose_refinement.hpp"
#include "select/excluded_rig.hpp"
#include "select/infeasibility.hpp"
#include "select/search_rules.hpp"

namespace rigdesign::select {
namespace {

constexpr double kSelectionTwoPi = 2 * std::numbers::pi;
constexpr int kMaxExactRejections = 50;

bool meets_alone(const CatalogOption& option, const SatisficingTargets& targets) {
  const metrics::MountMetrics& m = option.metrics;
  if (m.frequency < targets.min_frequency) return false;
  if (targets.max_spacing && m.point_spacing > *targets.max_spacing) return false;
  if (targets.max_noise && m.noise > *targets.max_noise) return false;
  for (const model::LightCondition condition : targets.lighting) {
    if (!m.light.immune_to(condition)) return false;
  }
  return true;
}

bool slot_allows(const model::MountingSlot& slot, const std::string& sensor_id) {
  return std::find(slot.allowed_sensors.begin(), slot.allowed_sensors.end(), sensor_id) !=
         slot.allowed_sensors.end();
}

// Under --robust n-1 every slot's sensor may fail. If at some angle of a required sector
// even every option of every other slot together cannot meet the sector, then no rig meets
// it: one without that slot falls short outright, one with it after its failure (the
// thresholds are the lower of the plain and the after-failure ones). Decided from the
// options' rasters before the search; names the sector, the slot and the angle.
std::optional<std::string> sector_needing_one_slot(
    const SearchProblem& problem, const std::vector<std::vector<const CatalogOption*>>& kept,
    const SatisficingTargets& targets, const SelectionSpace& space) {
  const model::Catalog& catalog = space.catalog();
  for (std::size_t i = 0; i < problem.robustness.sectors.size(); ++i) {
    const SearchSector& after = problem.robustness.sectors[i];
    const double min_complete = std::min(after.min_complete, problem.sectors[i].min_complete);
    const double min_floor = std::min(after.min_floor, problem.sectors[i].min_floor);
    if (!(min_complete > 0.0) && !(min_floor > 0.0)) continue;
    for (std::size_t failed = 0; failed < kept.size(); ++failed) {
      if (kept[failed].empty()) continue;
      for (const int a : after.angles) {
        const auto angle = static_cast<std::size_t>(a);
        geometry::SectionRaster others((*kept[failed].front()->sections)[angle].grid());
        for (std::size_t k = 0; k < kept.size(); ++k) {
          if (k == failed) continue;
          for (const CatalogOption* option : kept[k]) others |= (*option->sections)[angle];
        }
        if (meets(others.complete_share(), min_complete) && meets(others.floor_share(), min_floor))
          continue;
        const std::string slot = catalog.slots[kept[failed].front()->slot].id;
        return "under --robust n-1 the sector '" + targets.sectors[i].name + "' needs slot '" +
               slot + "': without it every other option together covers " +
               model::format_number(100 * others.complete_share(), 3) + " % (floor " +
               model::format_number(100 * others.floor_share(), 3) + " %) at " +
               model::format_number(model::rad_to_deg(space.angle(angle)), 4) + " deg, below " +
               model::format_number(100 * min_complete, 3) + " % (" +
               model::format_number(100 * min_floor, 3) +
               " %): no rig survives the failure of its sensor (a second slot that sees the "
               "sector, or robustness.sectors with a lower threshold after a failure)";
      }
    }
  }
  return std::nullopt;
}

// R1 and R3 against the catalog itself: a catalog for another body, or one whose options were
// judged at a shorter distance, cannot give the application a rig.
std::optional<std::string> catalog_mismatch(const model::Catalog& catalog,
                                            const model::Requirements& requirements,
                                            const SatisficingTargets& targets) {
  if (requirements.body_radius &&
      (std::abs(*requirements.body_radius - catalog.body.radius) > 1e-3 ||
       std::abs(*requirements.body_height - catalog.body.height) > 1e-3)) {
    return "R1: the catalog's body differs from the application's";
  }
  if (catalog.distance_of_interest + 1e-9 < targets.distance) {
    return "R3: the catalog's distance of interest " +
           model::format_number(catalog.distance_of_interest) + " m is below the required " +
           model::format_number(targets.distance) + " m";
  }
  return std::nullopt;
}

// A search's progress reported as the phase `phase`, which starts now: shown before the
// search builds its coverage classes, which takes a while on large catalogs.
std::function<void(const SearchProgress&)> search_progress_for(const ProgressSink& progress,
                                                               const std::string& phase) {
  if (progress) progress({phase, 0, 1, "", "0 nodes"});
  return [&progress, phase](const SearchProgress& at) {
    if (progress) progress({phase, at.fraction, 1.0, "", std::to_string(at.nodes) + " nodes"});
  };
}

// select_cheapest once the problem is set up: what its steps share. The steps: search for the
// cheapest rig not yet rejected, verify it on the exact path, accept it (its poses refined), and
// after the loop the price of robustness and the reason why no rig was found.
struct CheapestSearch {
  const SelectionSpace& space;
  const SatisficingTargets& targets;
  const ProgressSink& progress;
  bool probe;
  const SearchProblem& problem;
  const std::vector<std::vector<const CatalogOption*>>& kept;
  Selection& selection;
  metrics::CoverageSettings exact;  // the space's settings on the exact path
  PhaseClock clock{selection.phases, &progress};

  void run();
  bool search(const std::vector<std::vector<int>>& excluded);
  bool verify();
  void accept();
  void robustness_cost();
  void cheaper_rig(CheaperRigSearch& beside);
  void explain_infeasible();
};

// Raster winners the exact path rejects are excluded and the search repeated, up to
// kMaxExactRejections times.
void CheapestSearch::run() {
  std::vector<std::vector<int>> excluded;
  while (search(excluded)) {
    if (verify()) {
      accept();
      return;
    }
    excluded.push_back(selection.search.choice);
    if (++selection.rejected_by_exact_path >= kMaxExactRejections) return;
  }
}

// The cheapest rig on the rasters except `excluded`; false when there is none.
bool CheapestSearch::search(const std::vector<std::vector<int>>& excluded) {
  const std::string phase = excluded.empty()
                                ? std::string("search")
                                : "search " + std::to_string(excluded.size() + 1) +
                                      " (raster winners the exact path rejected excluded)";
  clock.start(phase);
  selection.search = branch_and_bound(problem, excluded, search_progress_for(progress, phase));
  clock.stop(std::to_string(selection.search.nodes) + " nodes, " +
             std::to_string(selection.search.evaluations) + " rigs evaluated");
  if (!selection.search.found) return false;
  selection.chosen.clear();
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const int index = selection.search.choice[k];
    if (index >= 0) selection.chosen.push_back(kept[k][index]);
  }
  selection.rig = space.rig_for(selection.chosen);
  return true;
}

// The rig's coverage on the exact path, then over the tolerance box and under the failures
// when the requirements ask for them; each only while the rig still passes.
bool CheapestSearch::verify() {
  clock.start("exact verification");
  if (progress) progress({"exact verification", 0, 1, "rigs", ""});
  selection.coverage =
      metrics::compute_coverage(selection.rig, space.library(), targets.sectors, exact);
  bool verified = std::all_of(selection.coverage.sectors.begin(), selection.coverage.sectors.end(),
                              [](const metrics::SectorCoverage& sector) { return sector.pass; });
  clock.stop(std::string("the rig's coverage on the exact path") + (verified ? "" : ": rejected"));
  if (verified && space.tolerance() && space.tolerance()->any()) {
    clock.start("exact verification over the tolerance box");
    selection.tolerance =
        metrics::tolerance_coverage(selection.rig, space.library(), targets.sectors, exact);
    verified = std::all_of(selection.tolerance.begin(), selection.tolerance.end(),
                           [](const metrics::SectorTolerance& sector) { return sector.pass; });
    clock.stop(std::to_string(selection.tolerance.size()) +
               " sectors at every mount's box corners and face centres" +
               (verified ? "" : ": rejected"));
  }
  if (verified && targets.robustness && targets.robustness->any()) {
    clock.start("exact verification of failures");
    selection.failures =
        failure_impacts(selection.rig, space, targets, exact, [&](double done, double total) {
          if (progress)
            progress({"exact verification of failures", done, total, "sector angles", ""});
        });
    verified = std::all_of(selection.failures.begin(), selection.failures.end(),
                           [](const FailureImpact& f) { return f.broken_sectors.empty(); });
    clock.stop(std::to_string(selection.failures.size()) +
               " failures, each mount's sections computed once" + (verified ? "" : ": rejected"));
  }
  return verified;
}

void CheapestSearch::accept() {
  selection.found = true;
  selection.cost = selection.search.cost;
  selection.grid_rig = selection.rig;
  // The refinement moves poses on nominal rasters: with a tolerance the grid's poses stay.
  if (!probe && !space.tolerance()) {
    clock.start("pose refinement");
    selection.refinement = refine_poses(space, selection, targets, progress);
    const PoseRefinement& r = selection.refinement;
    clock.stop(!r.tried ? std::string("no chosen slot has a pose range")
                        : std::to_string(r.evaluations) + " rigs on the raster path" +
                              (r.coverage.sectors.empty()
                                   ? std::string(", no pose moved")
                                   : std::string(", then the exact path: ") +
                                         (r.accepted ? "confirmed" : "rejected")));
  }
  if (selection.refinement.accepted) {
    selection.rig = selection.refinement.rig;
    selection.coverage = selection.refinement.coverage;
    if (!selection.refinement.failures.empty()) selection.failures = selection.refinement.failures;
  }
}

// Issue 55 item 3: the cheapest rig that meets the coverage and sensor requirements with
// free, unlimited CPU and transfer, when it is cheaper than the one chosen: the user sees
// what ruled it out instead of guessing. Its search ran beside the main one; this phase is
// the wait for it.
void CheapestSearch::cheaper_rig(CheaperRigSearch& beside) {
  const std::string phase = "why not cheaper (waiting for its search beside the main one)";
  clock.start(phase);
  if (progress)
    progress({phase, 0, 1, "searches", "a search with free, unlimited CPU and transfer"});
  selection.cheaper_excluded = beside.result(kept, selection.cost);
  selection.cheaper_searched = true;
  clock.stop(selection.cheaper_excluded ? "a rig with cheaper sensors lost on CPU or transfer"
                                        : "no rig with cheaper sensors meets the requirements");
}

// What robustness costs: the cheapest rig of a search without it.
void CheapestSearch::robustness_cost() {
  SearchProblem plain = problem;
  plain.robustness = {};
  clock.start("robustness cost");
  const SearchResult without = branch_and_bound(
      plain, {}, search_progress_for(progress, "robustness cost (search without it)"));
  clock.stop("a search without robustness: " + std::to_string(without.nodes) + " nodes");
  if (without.found) selection.cost_without_robustness = without.cost.total;
}

void CheapestSearch::explain_infeasible() {
  if (selection.rejected_by_exact_path >= kMaxExactRejections) {
    selection.infeasible_reason = "the exact path rejected the " +
                                  std::to_string(kMaxExactRejections) +
                                  " cheapest raster winners (thresholds within the raster's "
                                  "error of what the options reach)";
  } else if (!probe) {
    clock.start("cause");
    selection.infeasible_reason = infeasibility_cause(problem, space.options(), targets, space);
    clock.stop("searches relaxing one constraint at a time");
  } else {
    selection.infeasible_reason = "no combination of the catalog's options meets every requirement";
  }
}

// Where a slot's pose puts a sensor's data origin: there, or where its housing's bottom or
// back face sits there (model::HousingSeat).
model::Pose3 seated_pose(const model::Sensor& sensor, const model::Pose3& T_robot_seat,
                         model::HousingSeat seat) {
  if (!sensor.housing) return T_robot_seat;
  return T_robot_seat * Eigen::Translation3d(-sensor.housing->seat(seat));
}

// The sensor's housing at its data origin `T_robot_sensor` of a slot pose; null when it has
// none. `buildable` is false, and the reason counted in `reasons`, when the sensor cannot be
// bolted there: its origin, moved off the pose by a seat, inside the body (a pose's own point
// is judged once, by find_buried_poses), or its housing cutting into it.
std::shared_ptr<const geometry::ConvexSolid> housing_at(
    const model::Sensor& sensor, const model::Pose3& T_robot_sensor,
    const model::MountingSlot& slot, const model::SlotPose& pose, const model::Catalog& catalog,
    std::map<std::string, std::size_t>& reasons, bool& buildable) {
  buildable = true;
  if (!sensor.housing) return nullptr;
  const auto buried =
      slot.seat == model::HousingSeat::origin
          ? std::nullopt
          : geometry::burial(catalog, pose.housing_link, T_robot_sensor.translation());
  if (buried) {
    buildable = false;
    ++reasons[sensor.id + ", its data origin " + buried->describe()];
    return nullptr;
  }
  const std::vector<geometry::HousingClash> clashes =
      slot.recessed
          ? std::vector<geometry::HousingClash>{}
          : geometry::body_clashes(catalog, pose.housing_link, *sensor.housing, T_robot_sensor);
  if (!clashes.empty()) {
    buildable = false;
    ++reasons[sensor.id + ", its housing cutting into " + clashes.front().what()];
    return nullptr;
  }
  return std::make_shared<const geometry::ConvexSolid>(
      geometry::housing_solid(*sensor.housing, T_robot_sensor));
}

// Adds each slot's sensors left out for their housing to the poses left out, slot order.
std::vector<LeftOutPoses> with_sensor_reasons(
    const model::Catalog& catalog, std::vector<LeftOutPoses> buried,
    const std::vector<std::map<std::string, std::size_t>>& sensor_reasons) {
  std::vector<LeftOutPoses> merged;
  for (std::size_t k = 0; k < catalog.slots.size(); ++k) {
    const model::MountingSlot& slot = catalog.slots[k];
    const auto it = std::find_if(buried.begin(), buried.end(),
                                 [&](const LeftOutPoses& entry) { return entry.slot == slot.id; });
    LeftOutPoses entry =
        it != buried.end() ? *it : LeftOutPoses{slot.id, slot.where, slot.poses.size(), {}, {}};
    entry.sensor_reasons = sensor_reasons[k];
    if (!entry.reasons.empty() || !entry.sensor_reasons.empty()) merged.push_back(entry);
  }
  return merged;
}

}  // namespace

std::size_t count_catalog_options(const model::Catalog& catalog) {
  std::size_t count = 0;
  for (const model::MountingSlot& slot : catalog.slots) {
    std::size_t modes = 0;
    for (const model::CandidateSensor& candidate : catalog.sensors) {
      if (slot_allows(slot, candidate.sensor_id)) modes += candidate.mode_ids.size();
    }
    count += modes * slot.poses.size();
  }
  return count;
}

std::vector<model::SectorRequirement> robust_sectors(const SatisficingTargets& targets) {
  std::vector<model::SectorRequirement> sectors = targets.sectors;
  for (model::SectorRequirement& sector : sectors) {
    for (const model::SectorRequirement& relaxed : targets.robustness->sectors) {
      if (relaxed.name != sector.name) continue;
      sector.min_complete_coverage = relaxed.min_complete_coverage;
      sector.min_floor_coverage = relaxed.min_floor_coverage;
    }
  }
  return sectors;
}

std::vector<FailureImpact> failure_impacts(const model::Rig& rig, const SelectionSpace& space,
                                           const SatisficingTargets& targets,
                                           const metrics::CoverageSettings& settings,
                                           const std::function<void(double, double)>& progress) {
  std::vector<FailureImpact> impacts;
  std::vector<std::vector<bool>> failures;
  if (targets.robustness->single_failure) {
    for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
      failures.emplace_back(rig.mounts.size(), false);
      failures.back()[i] = true;
      impacts.push_back({rig.mounts[i].id + " fails", {}});
    }
  }
  if (targets.robustness->condition) {
    std::vector<bool> failed;
    std::vector<std::string> names;
    for (const model::Mount& mount : rig.mounts) {
      const model::SensorMode& mode = space.library().resolved_mode(mount.sensor_id, mount.mode_id);
      failed.push_back(!mode.light.immune_to(*targets.robustness->condition));
      if (failed.back()) names.push_back(mount.id);
    }
    failures.push_back(std::move(failed));
    impacts.push_back({to_string(*targets.robustness->condition) + ": " +
                           (names.empty() ? std::string("no sensor") : model::join(names)) +
                           " fail",
                       {}});
  }
  const std::vector<model::SectorRequirement> sectors = robust_sectors(targets);
  const std::vector<std::vector<std::size_t>> broken =
      metrics::sectors_broken_by(rig, space.library(), sectors, settings, failures, progress);
  for (std::size_t f = 0; f < impacts.size(); ++f)
    for (const std::size_t s : broken[f]) impacts[f].broken_sectors.push_back(sectors[s].name);
  return impacts;
}

SatisficingTargets satisficing_targets(const model::Requirements& requirements) {
  SatisficingTargets targets;
  targets.min_frequency = requirements.required_frequency();
  targets.max_spacing = requirements.smallest_obstacle;
  targets.max_noise = requirements.max_noise;
  targets.lighting = requirements.lighting;
  targets.sectors = requirements.sectors;
  targets.distance = requirements.distance;
  targets.robustness = requirements.robustness;
  return targets;
}

SelectionSpace::SelectionSpace(const model::Catalog& catalog, const model::SensorLibrary& library,
                               const metrics::CoverageSettings& settings,
                               const std::optional<model::PoseTolerance>& tolerance,
                               const ProgressSink& progress)
    : catalog_(&catalog), library_(&library), settings_(settings), tolerance_(tolerance) {
  const geometry::BodyOccluder body(catalog.body);
  const int angles = std::max(1, static_cast<int>(std::lround(kSelectionTwoPi / settings.step)));
  std::vector<geometry::SectionFrame> frames;
  for (int a = 0; a < angles; ++a) {
    frames.push_back(
        geometry::section_frame(body, kSelectionTwoPi * a / angles, catalog.distance_of_interest));
    grids_.push_back(
        {std::max(1, static_cast<int>(std::ceil(frames.back().width() / settings.raster_cell))),
         std::max(1, static_cast<int>(std::ceil(frames.back().h / settings.raster_cell)))});
  }
  place_options(progress);
  rasterise_options(body, frames, progress);
}

// Every slot pose and sensor that can be bolted on: the pose not inside the body, the
// housing not cutting into it; each mode an option with its metrics.
void SelectionSpace::place_options(const ProgressSink& progress) {
  const model::Catalog& catalog = *catalog_;
  PhaseClock clock(phases_, &progress);
  clock.start("placing");
  double poses_total = 0;
  for (const model::MountingSlot& slot : catalog.slots)
    poses_total += static_cast<double>(slot.poses.size());
  if (progress) progress({"placing", 0, poses_total, "slot poses", "inside the body?"});
  options_.resize(catalog.slots.size());
  BuriedPoses buried = find_buried_poses(catalog);
  std::vector<std::map<std::string, std::size_t>> sensor_reasons(catalog.slots.size());
  double poses_done = 0;
  for (std::size_t k = 0; k < catalog.slots.size(); ++k) {
    const model::MountingSlot& slot = catalog.slots[k];
    const double distance = slot.distance_of_interest.value_or(catalog.distance_of_interest);
    for (std::size_t p = 0; p < slot.poses.size(); ++p) {
      if (progress) progress({"placing", poses_done++, poses_total, "slot poses", "housings"});
      if (buried.buried[k][p]) continue;
      for (const model::CandidateSensor& candidate : catalog.sensors) {
        if (!slot_allows(slot, candidate.sensor_id)) continue;
        const model::Sensor* sensor = library_->find(candidate.sensor_id);
        model::Mount mount;
        mount.id = slot.id;
        mount.T_robot_sensor = seated_pose(*sensor, slot.poses[p].T_robot_sensor, slot.seat);
        bool buildable = true;
        const auto housing = housing_at(*sensor, mount.T_robot_sensor, slot, slot.poses[p], catalog,
                                        sensor_reasons[k], buildable);
        if (!buildable) continue;
        for (const std::string& mode_id : candidate.mode_ids) {
          CatalogOption option;
          option.slot = k;
          option.pose = p;
          option.T_robot_sensor = mount.T_robot_sensor;
          option.sensor = sensor;
          option.housing = housing;
          option.mode = sensor->find_mode(mode_id);
          option.metrics = metrics::compute_mount_metrics(mount, *sensor, *option.mode, distance);
          // U_f: filtering time per point times points per second (paper 1, eq. 5).
          option.filtering =
              candidate.filtering_seconds_per_point.value_or(catalog.filtering_seconds_per_point) *
              option.metrics.filtered_points_per_second;
          options_[k].push_back(std::move(option));
        }
      }
    }
  }
  left_out_ = with_sensor_reasons(catalog, std::move(buried.left_out), sensor_reasons);
  clock.stop(model::format_number(poses_total) + " slot poses tested against the body, " +
             std::to_string(option_count()) + " options left");
}

// Every option's sections at every angle, on every core; with a tolerance only the cells
// seen at every pose of the box.
void SelectionSpace::rasterise_options(const geometry::BodyOccluder& body,
                                       const std::vector<geometry::SectionFrame>& frames,
                                       const ProgressSink& progress) {
  const model::Catalog& catalog = *catalog_;
  PhaseClock clock(phases_, &progress);
  clock.start("rasterising");
  std::vector<CatalogOption*> all;
  for (auto& slot : options_)
    for (CatalogOption& option : slot) all.push_back(&option);
  const double total = static_cast<double>(all.size());
  // The poses each option is rasterised at: the nominal one, and the tolerance box's samples.
  std::vector<metrics::PoseError> errors = {metrics::PoseError{}};
  if (tolerance_ && tolerance_->any()) {
    for (const metrics::PoseError& error : metrics::tolerance_samples(*tolerance_))
      errors.push_back(error);
  }
  const std::string detail =
      std::to_string(grids_.size()) + " angles each" +
      (errors.size() > 1 ? ", " + std::to_string(errors.size()) + " poses of the tolerance box"
                         : std::string());
  if (progress) progress({"rasterising", 0, total, "options", detail});
  std::mutex heard;  // the sink hears one thread at a time
  std::size_t done = 0;
  const int angles = static_cast<int>(grids_.size());
  const int threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  model::parallel_for(all.size(), threads, [&](std::size_t i) {
    CatalogOption& option = *all[i];
    const model::SlotPose& slot_pose = catalog.slots[option.slot].poses[option.pose];
    const model::Pose3& nominal = option.T_robot_sensor;
    // With a tolerance a mode with an FOV spread is judged at its narrowest (a subset of the
    // nominal FOV's directions, so the nominal pose's cells are kept only where it sees too).
    const model::SensorMode narrowed = option.mode->narrowest();
    const model::SensorMode& judged = tolerance_ ? narrowed : *option.mode;
    std::vector<geometry::SectionRaster> sections;
    for (const metrics::PoseError& error : errors) {
      const geometry::MountedFov fov(judged, metrics::with_error(nominal, error), body,
                                     slot_pose.housing_link);
      for (int a = 0; a < angles; ++a) {
        geometry::SectionRaster seen = geometry::rasterize(fov, frames[a], grids_[a]);
        if (sections.size() < static_cast<std::size_t>(angles)) {
          sections.push_back(std::move(seen));
        } else {
          sections[a] &= seen;  // seen at every pose so far
        }
      }
    }
    option.sections =
        std::make_shared<const std::vector<geometry::SectionRaster>>(std::move(sections));
    const std::lock_guard<std::mutex> lock(heard);
    ++done;
    if (progress) progress({"rasterising", static_cast<double>(done), total, "options", detail});
  });
  clock.stop(std::to_string(all.size()) + " options, " + detail);
}

std::vector<std::size_t> SelectionSpace::options_per_slot() const {
  std::vector<std::size_t> counts;
  for (const auto& slot : options_) counts.push_back(slot.size());
  return counts;
}

std::size_t SelectionSpace::option_count() const {
  std::size_t count = 0;
  for (const auto& slot : options_) count += slot.size();
  return count;
}

double SelectionSpace::angle(std::size_t index) const {
  return kSelectionTwoPi * static_cast<double>(index) / static_cast<double>(grids_.size());
}

SearchProblem SelectionSpace::problem_for(
    const SatisficingTargets& targets, std::vector<std::vector<const CatalogOption*>>& kept) const {
  SearchProblem problem;
  problem.grids = grids_;
  problem.transfer = catalog_->transfer;
  problem.cpus = catalog_->cpus;
  kept.assign(options_.size(), {});
  for (std::size_t k = 0; k < options_.size(); ++k) {
    problem.slots.emplace_back();
    // The slot's support is bought with whichever sensor is chosen there.
    const std::optional<model::RigSupport>& support = catalog_->slots[k].support;
    const double support_price = support ? support->price : 0.0;
    for (const CatalogOption& option : options_[k]) {
      if (!meets_alone(option, targets)) continue;
      const bool survives = !targets.robustness || !targets.robustness->condition ||
                            option.metrics.light.immune_to(*targets.robustness->condition);
      problem.slots.back().push_back(
          {option.metrics.price + support_price, option.metrics.bandwidth,
           option.metrics.driver_cpu + option.filtering, option.sections, survives, option.housing,
           per_sensor_transfer_price(catalog_->transfer, option.metrics.bandwidth)});
      kept[k].push_back(&option);
    }
  }
  for (const model::SectorRequirement& sector : targets.sectors) {
    SearchSector searched{{}, sector.min_complete_coverage, sector.min_floor_coverage};
    for (std::size_t a = 0; a < grids_.size(); ++a) {
      if (metrics::in_sector(sector, angle(a))) searched.angles.push_back(static_cast<int>(a));
    }
    problem.sectors.push_back(std::move(searched));
  }
  if (targets.robustness && targets.robustness->any()) {
    const model::RobustnessRequirement& robust = *targets.robustness;
    problem.robustness.single_failure = robust.single_failure;
    problem.robustness.condition = robust.condition.has_value();
    for (std::size_t i = 0; i < targets.sectors.size(); ++i) {
      SearchSector after = problem.sectors[i];
      for (const model::SectorRequirement& relaxed : robust.sectors) {
        if (relaxed.name != targets.sectors[i].name) continue;
        after.min_complete = relaxed.min_complete_coverage;
        after.min_floor = relaxed.min_floor_coverage;
      }
      problem.robustness.sectors.push_back(std::move(after));
    }
  }
  return problem;
}

model::Rig SelectionSpace::rig_for(const std::vector<const CatalogOption*>& chosen) const {
  model::Rig rig;
  rig.name = catalog_->name + " (selected)";
  static_cast<model::DescribedRobot&>(rig) = *catalog_;
  rig.file = catalog_->file;
  rig.tolerance = tolerance_;
  for (const CatalogOption* option : chosen) {
    const model::MountingSlot& slot = catalog_->slots[option->slot];
    model::Mount mount;
    mount.id = slot.id;
    mount.sensor_id = option->sensor->id;
    mount.mode_id = option->mode->id;
    mount.T_robot_sensor = option->T_robot_sensor;
    mount.recessed = slot.recessed;
    mount.urdf_link = slot.poses[option->pose].urdf_link;
    mount.urdf_link_optical = slot.poses[option->pose].urdf_link_optical;
    mount.housing_link = slot.poses[option->pose].housing_link;
    mount.distance_of_interest = slot.distance_of_interest;
    rig.mounts.push_back(mount);
    if (slot.support) rig.supports.push_back(*slot.support);
  }
  return rig;
}

Selection select_cheapest(const SelectionSpace& space, const model::Requirements& requirements,
                          const ProgressSink& progress, bool probe) {
  const auto start = std::chrono::steady_clock::now();
  Selection selection;
  const SatisficingTargets targets = satisficing_targets(requirements);
  const auto finish = [&] {
    selection.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(selection);
  };
  if (auto reason = catalog_mismatch(space.catalog(), requirements, targets)) {
    selection.infeasible_reason = std::move(*reason);
    return finish();
  }
  std::vector<std::vector<const CatalogOption*>> kept;
  const SearchProblem problem = space.problem_for(targets, kept);
  if (problem.robustness.single_failure) {
    if (auto reason = sector_needing_one_slot(problem, kept, targets, space)) {
      selection.infeasible_reason = std::move(*reason);
      return finish();
    }
  }
  metrics::CoverageSettings exact = space.settings();
  exact.exact = true;
  CheapestSearch search{space, targets, progress, probe, problem, kept, selection, exact};
  std::optional<CheaperRigSearch> beside;
  if (!probe) beside.emplace(problem);
  search.run();
  if (selection.found && beside) search.cheaper_rig(*beside);
  beside.reset();  // stopped if the main search found no rig
  if (problem.robustness.any() && !probe) search.robustness_cost();
  if (!selection.found && selection.infeasible_reason.empty()) search.explain_infeasible();
  return finish();
}

}  // namespace rigdesign::select
