#pragma once
/// `select`'s main step (paper 1, section 2, Fig. 1): from application requirements to
/// satisficing metrics, and the cheapest rig of a catalog that meets them, found on the
/// raster path and verified on the exact path.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/mount_metrics.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/select/buried_poses.hpp"
#include "rigdesign/select/phase_progress.hpp"
#include "rigdesign/select/search.hpp"

namespace rigdesign::select {

/// The satisficing metrics requirements R1-R8 ask for (DESIGN.md section 5).
struct SatisficingTargets {
  double min_frequency = 0.0;                     ///< F >= [Hz]: R3's rate, R4 and R5's v / travel
  std::optional<double> max_spacing;              ///< R <= [m]: R6's smallest obstacle
  std::optional<double> max_noise;                ///< N <= [m]: R7
  std::vector<model::LightCondition> lighting;    ///< L: R8
  std::vector<model::SectorRequirement> sectors;  ///< SC per sector: R2
  double distance = 0.0;                          ///< d [m]: R3
  /// Failures the rig must survive and the thresholds after them (issue 15); none if unset.
  std::optional<model::RobustnessRequirement> robustness;
};

SatisficingTargets satisficing_targets(const model::Requirements& requirements);

/// One sensor mode in one slot, with its metrics and its raster sections.
struct CatalogOption {
  std::size_t slot = 0;
  std::size_t pose = 0;  ///< index into the slot's poses
  /// The sensor's data origin: the slot pose's, moved by the slot's seat (a housing's bottom
  /// or back face placed at the pose).
  model::Pose3 T_robot_sensor = model::Pose3::Identity();
  const model::Sensor* sensor = nullptr;
  const model::SensorMode* mode = nullptr;
  metrics::MountMetrics metrics;  ///< at the slot's distance of interest
  double filtering = 0.0;         ///< U_f [core-equivalents]
  std::shared_ptr<const std::vector<geometry::SectionRaster>> sections;  ///< per angle of the space
  std::shared_ptr<const geometry::ConvexSolid> housing;  ///< at the pose; null: none
};

/// How many options a catalog gives: per slot, its poses times the modes of the sensors it
/// allows. Known before any rasterising, so `select` can bound the work it is about to do.
std::size_t count_catalog_options(const model::Catalog& catalog);

/// Every option of a catalog rasterised once; searches for different requirements reuse it.
/// With a mounting tolerance (issue 38: `select --tolerance`) an option's raster keeps only
/// the cells it sees at its nominal pose and at every sample of the tolerance box
/// (metrics::tolerance_samples): a union of such rasters is seen wherever in their boxes the
/// mounts sit (at the samples), so a rig the search accepts meets the sectors over the box,
/// and the search's leximin tie-break prefers the poses whose worst case keeps the largest
/// margins. Options are rasterised on every core. `progress` hears two phases: "placing"
/// (slot poses and housings tested against the body, counted in slot poses) and
/// "rasterising" (counted in options, heard from one thread at a time).
class SelectionSpace {
 public:
  SelectionSpace(const model::Catalog& catalog, const model::SensorLibrary& library,
                 const metrics::CoverageSettings& settings = {},
                 const std::optional<model::PoseTolerance>& tolerance = {},
                 const ProgressSink& progress = {});

  const model::Catalog& catalog() const { return *catalog_; }
  const model::SensorLibrary& library() const { return *library_; }
  const metrics::CoverageSettings& settings() const { return settings_; }
  /// The tolerance every option is rasterised over; nothing: the nominal poses.
  const std::optional<model::PoseTolerance>& tolerance() const { return tolerance_; }
  const std::vector<geometry::RasterGrid>& grids() const { return grids_; }
  std::size_t option_count() const;
  /// The slot poses left out before rasterising: the sensor would be inside the body.
  const std::vector<LeftOutPoses>& left_out() const { return left_out_; }
  /// How long placing and rasterising took, in order.
  const std::vector<PhaseTime>& phases() const { return phases_; }
  /// Per slot, how many options it gave (its poses left in times the modes allowed there).
  std::vector<std::size_t> options_per_slot() const;
  /// Every option, per slot (before any requirement filters them).
  const std::vector<std::vector<CatalogOption>>& options() const { return options_; }
  double angle(std::size_t index) const;

  /// The search problem for `targets`: per slot, the options that meet F, R, N and L on
  /// their own (those metrics are the worst sensor's, so every sensor must meet them);
  /// `kept[k][i]` is the option behind the problem's option i of slot k.
  SearchProblem problem_for(const SatisficingTargets& targets,
                            std::vector<std::vector<const CatalogOption*>>& kept) const;

  /// The rig an assignment describes: one mount per chosen slot.
  model::Rig rig_for(const std::vector<const CatalogOption*>& chosen) const;

 private:
  const model::Catalog* catalog_;
  const model::SensorLibrary* library_;
  metrics::CoverageSettings settings_;
  std::optional<model::PoseTolerance> tolerance_;
  std::vector<geometry::RasterGrid> grids_;
  std::vector<std::vector<CatalogOption>> options_;  // per slot
  std::vector<LeftOutPoses> left_out_;
  std::vector<PhaseTime> phases_;

  void place_options(const ProgressSink& progress);
  void rasterise_options(const geometry::BodyOccluder& body,
                         const std::vector<geometry::SectionFrame>& frames,
                         const ProgressSink& progress);
};

/// One failure the chosen rig was checked against (exact path) and the sectors it breaks.
struct FailureImpact {
  std::string failure;  ///< "<mount id> fails", or "sunlight: <mounts> fail"
  std::vector<std::string> broken_sectors;
};

/// One axis moved by the refinement, SI (m, rad).
struct RefinedAxis {
  std::string mount;
  int axis = 0;  ///< model::PoseAxisRange::axis
  double low = 0.0;
  double high = 0.0;
  double grid = 0.0;     ///< the search's value
  double refined = 0.0;  ///< the refinement's value
};

struct PoseRefinement {
  bool tried = false;           ///< some chosen slot has a pose range
  bool accepted = false;        ///< the exact path confirms the refined rig
  double grid_margin = 0.0;     ///< smallest raster margin of the grid optimum [share]
  double refined_margin = 0.0;  ///< of the refined poses
  /// The margins compared include each after-failure margin (robustness asked).
  bool counts_failures = false;
  int evaluations = 0;  ///< rigs rasterised by the compass search
  std::vector<RefinedAxis> axes;
  std::vector<std::array<double, 6>> values;  ///< per mount: its pose values after refinement
  model::Rig rig;                             ///< the refined rig
  metrics::RigCoverage coverage;              ///< its exact path
  std::vector<FailureImpact> failures;        ///< with robustness: its failures on the exact path
};

/// Issue 55 item 3: a rig cheaper than the chosen one in its sensors that meets the
/// coverage and sensor requirements (and survives the failures asked), but that the
/// catalog's CPUs or transfer rule out, or whose CPU and transfer cost more than they save.
/// The cheapest such rig, from a search with the CPU and transfer free and unlimited.
struct ExcludedRig {
  std::vector<const CatalogOption*> chosen;  ///< its options
  double sensor_cost = 0.0;                  ///< [USD] sensors and supports
  double cpu = 0.0;                          ///< U [core-equivalents] it needs
  double largest_cpu = 0.0;                  ///< the catalog's largest CPU [core-equivalents]
  std::string largest_cpu_id;
  double bandwidth = 0.0;            ///< B [bytes/s] it sends
  double transfer_bottleneck = 0.0;  ///< [bit/s] the most the catalog's transfer carries
  std::string transfer_bottleneck_id;
  /// Some sensor of it needs a per-sensor transfer component the catalog does not have.
  bool per_sensor_transfer_missing = false;
  bool cpu_too_small = false;       ///< no catalog CPU carries U
  bool transfer_too_small = false;  ///< no catalog transfer carries B (or a sensor's share)
  /// With the catalog's CPU and transfer (feasible false: they cannot carry it).
  CostBreakdown cost;
};

struct Selection {
  bool found = false;
  std::string infeasible_reason;  ///< when nothing can meet the requirements
  model::Rig rig;
  std::vector<const CatalogOption*> chosen;
  CostBreakdown cost;
  SearchResult search;            ///< of the last (accepted) search
  metrics::RigCoverage coverage;  ///< the winner on the exact path
  /// With a tolerance: each sector over the box on the exact path (all met).
  std::vector<metrics::SectorTolerance> tolerance;
  int rejected_by_exact_path = 0;  ///< raster winners the exact path turned down
  double seconds = 0.0;
  /// With robustness: each failure of the chosen rig (all survived), and the cheapest rig's
  /// cost without robustness (raster path), the price of robustness being the difference.
  std::vector<FailureImpact> failures;
  std::optional<double> cost_without_robustness;
  /// Continuous refinement of the chosen poses (pose_refinement.hpp); when accepted, `rig`,
  /// `coverage` and `failures` are the refined rig's and `grid_rig` the search's.
  PoseRefinement refinement;
  model::Rig grid_rig;
  std::vector<PhaseTime> phases;  ///< what ran, in order, and how long
  /// Why a cheaper rig lost (found rigs only, not in probes); none: no cheaper rig meets the
  /// coverage and sensor requirements even with free, unlimited CPU and transfer.
  std::optional<ExcludedRig> cheaper_excluded;
  bool cheaper_searched = false;  ///< that search ran (not in probes, not without a rig)
};

/// The sectors a robust rig must keep after a failure: the targets' with relaxed thresholds.
std::vector<model::SectorRequirement> robust_sectors(const SatisficingTargets& targets);

/// Each failure the targets ask `rig` to survive, on the path `settings` says.
/// `progress` hears (sector angles done, in total).
std::vector<FailureImpact> failure_impacts(
    const model::Rig& rig, const SelectionSpace& space, const SatisficingTargets& targets,
    const metrics::CoverageSettings& settings,
    const std::function<void(double, double)>& progress = {});

/// The cheapest rig meeting `requirements`, proven optimal on the raster path and verified
/// on the exact path (a raster winner the exact path rejects is excluded and the search
/// runs again).
/// `progress` hears every phase (search, exact verification, pose refinement, robustness
/// cost, the cause when there is no rig). `probe`: the search and its exact verification
/// only, as the binding-requirement probes need (no refinement, robustness cost or cause).
Selection select_cheapest(const SelectionSpace& space, const model::Requirements& requirements,
                          const ProgressSink& progress = {}, bool probe = false);

}  // namespace rigdesign::select
