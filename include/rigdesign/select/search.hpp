#pragma once
/// The exact minimum-cost search over slot assignments (each slot: nothing or one option),
/// on precomputed raster sections. Branch and bound, admissible because both the cost and
/// the coverage only grow when a sensor is added:
/// - a node no cheaper than the incumbent is cut, and so is one whose cost plus the cheapest
///   option that could still fill its worst uncovered angle is no cheaper;
/// - the union with every option of every undecided slot is an upper bound on the coverage
///   any completion reaches, so a node whose bound misses a sector threshold is cut;
/// - a node whose chosen sensors already meet every threshold needs nothing more;
/// - an option another of its slot dominates (no dearer in price, bandwidth and CPU, covering
///   a superset, surviving whatever it survives) is never tried.
/// The search runs on ClassCoverage (cells covered by the same options merged), exact to the
/// cell. Among rigs of equal cost (within kCostTie) the one with the largest smallest margin
/// to the sector thresholds wins, then the largest next smallest (leximin over the sectors'
/// margins), so a pose range's most robust pose is chosen, not the first found.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/section_raster.hpp"
#include "rigdesign/select/cost_model.hpp"

namespace rigdesign::select {

struct SearchOption {
  double price = 0.0;      ///< [USD]
  double bandwidth = 0.0;  ///< [bytes/s]
  double cpu = 0.0;        ///< [core-equivalents]
  /// One per angle of the problem; shared with the catalog option it came from (a catalog
  /// of 150 options holds 54,000 rasters: copied per relaxation step they would not fit).
  std::shared_ptr<const std::vector<geometry::SectionRaster>> sections;
  const geometry::SectionRaster& section(std::size_t angle) const { return (*sections)[angle]; }
  /// For robustness to a degraded condition: whether the option keeps working in it.
  bool survives_condition = true;
  /// The sensor's housing at the option's pose (issue 52 item 2); null: none. Two options
  /// whose housings overlap (geometry::kHousingTouch) are never chosen together.
  std::shared_ptr<const geometry::ConvexSolid> housing;
  /// [USD] the per-sensor transfer components (a cable, a port) this option's bandwidth needs
  /// (select::per_sensor_transfer_price); +infinity when the catalog has none that carries it.
  double transfer_price = 0.0;
};

/// Whether two options' housings cut into each other.
bool housings_clash(const SearchOption& a, const SearchOption& b);

/// SC thresholds over some of the problem's angles (R2).
struct SearchSector {
  std::vector<int> angles;
  double min_complete = 0.0;
  double min_floor = 0.0;
};

/// What a rig must survive (issue 15): any one sensor failing, and/or a condition in which
/// every option without `survives_condition` drops out at once; after each failure the rig
/// must still meet `sectors` (the problem's own, or a relaxed set).
struct Robustness {
  bool single_failure = false;
  bool condition = false;
  std::vector<SearchSector> sectors;
  bool any() const { return single_failure || condition; }
};

struct SearchProblem {
  std::vector<std::vector<SearchOption>> slots;
  std::vector<SearchSector> sectors;
  Robustness robustness;
  std::vector<model::PricedCapacity> transfer;
  std::vector<model::PricedCapacity> cpus;
  std::vector<geometry::RasterGrid> grids;  ///< per angle
  /// Only rigs cheaper than this [USD] are of interest: the cost bound starts here instead of
  /// at +infinity (a search for a cheaper rig than one already known).
  double cost_below = std::numeric_limits<double>::infinity();
  /// Among rigs of equal cost, search on for the largest margins (leximin); false: the first
  /// cheapest rig found is the answer (a search that asks only what the cheapest rig costs).
  bool widen_margins = true;
};

/// A rig the search found meeting every requirement, for the cost-versus-coverage Pareto plot.
struct ExploredRig {
  double cost = 0.0;
  double mean_complete = 0.0;  ///< SC complete over the problem's angles (raster)
  bool feasible = false;
};

/// Where a running search is: nodes visited, and the share of the tree behind it (the
/// depth-first position read as a mixed-radix fraction: an estimate, as cut subtrees differ
/// in size).
struct SearchProgress {
  long nodes = 0;
  double fraction = 0.0;
};

struct SearchResult {
  bool found = false;
  std::vector<int> choice;  ///< per slot: option index, or -1 for nothing
  CostBreakdown cost;
  /// The chosen rig's smallest margin over the sectors' angles: min(SC - threshold) over SC
  /// complete and floor (raster); +infinity without sectors.
  double margin = 0.0;
  std::vector<double> margins;  ///< each sector's smallest margin, smallest first (leximin)
  /// feasible rigs evaluated at the optimum's cost (1: no tie to break); the branch and bound
  /// cuts equal-cost subtrees that cannot widen the margins, so it may count fewer than exist
  long ties = 0;
  long nodes = 0;             ///< nodes of the search tree visited
  long evaluations = 0;       ///< rigs whose coverage was evaluated
  long dominated = 0;         ///< options never tried: another of their slot dominates them
  long raster_cells = 0;      ///< cells and floor columns of one rig's rasters, all angles
  long coverage_classes = 0;  ///< the classes they compress to (ClassCoverage)
  long housing_clashes = 0;   ///< pairs of options whose housings overlap (never chosen together)
  std::vector<ExploredRig> explored;  ///< the feasible rigs found
};

/// Coverage shares count as meeting a threshold from threshold - kThresholdSlack.
inline constexpr double kThresholdSlack = 1e-4;
/// Costs this close [USD] are equal, and the margin decides between them.
inline constexpr double kCostTie = 1e-6;

/// Proven-optimal assignment, skipping the assignments in `excluded` (used when the exact
/// path rejects a raster winner). `progress` is called now and then.
SearchResult branch_and_bound(const SearchProblem& problem,
                              const std::vector<std::vector<int>>& excluded = {},
                              const std::function<void(const SearchProgress&)>& progress = {});

/// Every assignment, for tests and the benchmark's ratio.
SearchResult brute_force(const SearchProblem& problem);

}  // namespace rigdesign::select
