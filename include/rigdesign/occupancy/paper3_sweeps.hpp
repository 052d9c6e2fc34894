#pragma once
/// Paper 3's parameter sweeps (Gomes, Oliveira, Santos, Tables 2-9; the numbers are in
/// ../shared/DESIGN.md section 9): each sweep's settings as paper 3 varied them, with its
/// reported scores, the mappers that run them here, and the trends the paper states, checked
/// on the paper's own numbers and on ours.
///
/// Reference rows (the settings a sweep holds while varying one), inferred from the tables
/// where the text does not say (docs/occupancy.md): OctoMap 0.1 m, hit 1, miss 0.4; SkiMap
/// 0.1 m, the lowest minimum weight; Voxblox voxel 0.1 m, truncation 0.1 m, 1/z^2 weights.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/occupancy/occupancy_evaluation.hpp"
#include "rigdesign/occupancy/octomap_mapper.hpp"
#include "rigdesign/occupancy/skimap_mapper.hpp"
#include "rigdesign/occupancy/voxblox_mapper.hpp"

namespace rigdesign::occupancy {

enum class Paper3Mapper { octomap, skimap, voxblox };

/// One row of a sweep.
struct Paper3Setting {
  std::string label;   ///< the swept value as the paper's table prints it
  double value = 0.0;  ///< the swept value as a number (true = 1, false = 0)
  Paper3Mapper mapper = Paper3Mapper::octomap;
  OctoMapParams octomap;
  SkiMapParams skimap;
  VoxbloxParams voxblox;
  Scores paper;  ///< paper 3's P, R, F1, F2, F3 for the row
};

struct Paper3Sweep {
  std::string name;   ///< "octomap:resolution", as `occupancy --sweep` takes it
  std::string table;  ///< "Tab. 2"
  std::string swept;  ///< "voxel length [m]"
  std::vector<Paper3Setting> rows;
};

/// What every mapper of the sweeps shares with the evaluation.
struct Paper3Common {
  double min_height = 0.1;   ///< [m] lower points clear but never mark (never count: SkiMap)
  double z_max = 2.0;        ///< [m]
  double window_size = 6.0;  ///< [m] Voxblox's dense window
};

/// octomap:resolution, octomap:hit, octomap:miss, skimap:resolution, skimap:min_weight,
/// voxblox:resolution, voxblox:truncation, voxblox:const_weight (paper 3's table order).
std::vector<std::string> paper3_sweep_names();
/// Throws std::invalid_argument for a name not in paper3_sweep_names().
Paper3Sweep paper3_sweep(const std::string& name, const Paper3Common& common = {});

/// The mapper of a row; its name() is the row's key in a run (equal settings, equal names).
/// Voxblox takes each sensor's depth axis from its mode (a camera's optical axis).
std::unique_ptr<OccupancyMapper> make_paper3_mapper(const Paper3Setting& row,
                                                    std::span<const CellSensor> sensors);
std::string paper3_mapper_name(const Paper3Setting& row);

/// A trend paper 3 states, checked on its own table and on our run of the same sweep(s).
struct Paper3Trend {
  std::string statement;
  std::string sweeps;  ///< the sweep(s) it reads
  bool holds_in_paper = false;
  bool holds_here = false;
  std::string paper_detail;  ///< the numbers it was decided on
  std::string our_detail;
};

/// Our scores of a row: the run whose mapper has the row's name; NaN scores when none.
using RunLookup = std::function<const OccupancyRun*(const std::string& mapper_name)>;

/// The trends whose sweeps are among `sweeps`: precision rising with voxel length (each
/// mapper), OctoMap's recall peaking near 0.1 m and SkiMap's at 0.075-0.1 m, Voxblox's recall
/// dropping below 0.15 m, a voxel/truncation ratio >= 1.5 beating 1 and 0.5, constant weight
/// lowering Voxblox's recall, hit 1 best and miss 0.7 collapsing for OctoMap, and SkiMap
/// keeping the actor's trail (more trail area shown than OctoMap at 0.1 m; no number in the paper,
/// so "holds in paper" means stated).
std::vector<Paper3Trend> paper3_trends(std::span<const Paper3Sweep> sweeps, const RunLookup& runs);

}  // namespace rigdesign::occupancy
