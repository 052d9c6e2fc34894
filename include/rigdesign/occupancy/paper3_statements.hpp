#pragma once
/// Every quantitative statement paper 3 makes about its sweeps (issue 54 item 2), checked on
/// the paper's own tables and on a run of the same sweeps: what its text states (as
/// ../shared/DESIGN.md section 9 and issue 54 quote it) and, table by table, which setting
/// gives the best precision, recall and F1 (what each table shows without a sentence).
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "rigdesign/occupancy/paper3_sweeps.hpp"

namespace rigdesign::occupancy {

/// A statement, checked on paper 3's table and on our run of the same sweep(s).
struct Paper3Trend {
  std::string statement;
  std::string sweeps;  ///< the sweep(s) it reads
  bool holds_in_paper = false;
  bool holds_here = false;
  std::string paper_detail;  ///< the numbers it was decided on
  std::string our_detail;
  bool from_text = true;  ///< stated in the text; false: read off a table (best setting)
};

/// Our scores of a row: the run whose mapper has the row's name; nullptr when none.
using RunLookup = std::function<const OccupancyRun*(const std::string& mapper_name)>;

/// The statements whose sweeps are among `sweeps` (a statement needing a sweep with no run is
/// left out). From the text: precision rising with voxel length (each mapper); OctoMap's
/// recall peaking near 0.1 m and SkiMap's at 0.075-0.1 m; Voxblox's recall dropping below
/// 0.15 m; F1 peaking near 0.15 m (each mapper); a voxel/truncation ratio of 2 beating 1 and
/// 0.5; constant weight lowering Voxblox's recall; hit 1 best and precision about equal at hit
/// 0.7 and 1; miss 0.7 collapsing; minimum weight 1 best for SkiMap; recall below precision
/// (each mapper's reference row); SkiMap best of the three by F1 at the reference rows; SkiMap
/// keeping the actor's trail (no number in the paper: "holds in paper" means stated). From the
/// tables: each table's best setting by P, R and F1.
std::vector<Paper3Trend> paper3_trends(std::span<const Paper3Sweep> sweeps, const RunLookup& runs);

}  // namespace rigdesign::occupancy
