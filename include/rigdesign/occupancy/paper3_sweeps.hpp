#pragma once
/// Paper 3's parameter sweeps (Gomes, Oliveira, Santos, Tables 2-9; the numbers are in
/// ../shared/DESIGN.md section 9): each sweep's settings as paper 3 varied them, with its
/// reported scores and the mappers that run them here (paper3_statements.hpp checks what the
/// paper states on its numbers and on ours).
///
/// Reference rows (the settings a sweep holds while varying one), inferred from the tables
/// where the text does not say (docs/occupancy.md): OctoMap 0.1 m, hit 1, miss 0.4; SkiMap
/// 0.1 m, the lowest minimum weight; Voxblox voxel 0.1 m, truncation 0.1 m, 1/z^2 weights.
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

/// What every mapper of the sweeps shares with the evaluation. Each peer's lowest marking
/// height is its ROS front end's default, not the evaluation's min_height: octomap_server
/// (filter_ground false, pointcloud_min_z -DBL_MAX) and voxblox_ros (no height filter) insert
/// every point; skimap_ros's map service drops points with z < 0.01 m (camera_min_z) in the
/// frame of the cloud it is given, here the cell's (docs/occupancy.md cites each).
struct Paper3Common {
  double min_height = 0.1;   ///< [m] the evaluation's; kept for the names of older runs
  double z_max = 2.0;        ///< [m]
  double window_size = 6.0;  ///< [m] Voxblox's dense window
  VoxbloxOccupiedRule voxblox_rule = VoxbloxOccupiedRule::occupied_nodes;
};

/// [m] skimap_ros's skimap_map_service camera_min_z default (m4nh/skimap_ros 9e2ce55,
/// src/nodes/skimap_map_service.cpp L234-235, L315).
inline constexpr double kSkiMapServiceMinZ = 0.01;

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

/// The reference row of a mapper: the settings every sweep of it holds while varying one, with
/// its front end's defaults (Paper3Common).
Paper3Setting paper3_reference(Paper3Mapper mapper, const Paper3Common& common = {});

}  // namespace rigdesign::occupancy
