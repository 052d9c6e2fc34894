#pragma once
// What `occupancy` found on the cell: every mapper's scores near the person, the whole-cell
// measures per phase (robot moving, standing), paper 3's sweeps beside its numbers, and the
// Pareto front; as the summary JSON, the per-frame CSV and the text the command prints.
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "rigdesign/occupancy/occupancy_evaluation.hpp"
#include "rigdesign/occupancy/occupancy_sweep.hpp"
#include "rigdesign/occupancy/paper3_sweeps.hpp"

namespace rigdesign::report {

struct OccupancyReport {
  std::string rig_name;
  std::string scene;
  std::size_t sensors = 0;
  double rate = 0.0;          ///< [Hz]
  double duration = 0.0;      ///< [s]
  double moving_until = 0.0;  ///< [s]
  int camera_stride = 1;
  int camera_pooling = 1;
  occupancy::TruthKind truth = occupancy::TruthKind::link_volumes;
  occupancy::ScoringRegion region = occupancy::ScoringRegion::hull;
  double object_margin = 0.0;  ///< [m], for the box-margin region
  std::vector<occupancy::OccupancyRun> runs;
  /// Our voxel mappers' settings, the first runs' (one each); paper 3's mappers follow.
  std::vector<occupancy::VoxelMapperParams> grid;
  std::vector<occupancy::Paper3Sweep> sweeps;
  std::vector<std::string> extra;   ///< our mappers' names, the rows beside paper 3's
  std::vector<std::string> pareto;  ///< the Pareto-optimal runs' labels
  std::string folder;               ///< where the files went; empty: none written
};

/// A run's label in the Pareto plot and list: our mapper's voxel and persistence, or the
/// peer mapper's name.
std::string occupancy_run_label(const OccupancyReport& report, std::size_t run);
nlohmann::json occupancy_json(const OccupancyReport& report);
/// One line per mapper and frame (occupancy_frames.csv).
std::string occupancy_frames_csv(const std::vector<occupancy::OccupancyRun>& runs);
void print_occupancy(const OccupancyReport& report, std::ostream& out);

}  // namespace rigdesign::report
