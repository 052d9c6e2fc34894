#pragma once
/// Seeded synthetic RSSI logs for paper 4's four field scenarios: a log-distance path-loss
/// model, log-normal shadowing correlated along the path (Gudmundson: correlation
/// exp(-distance / decorrelation distance)), optional attenuation per wall or door the line of
/// sight crosses, and noise on the logged robot position. Deterministic for a seed (within
/// one standard library: std::normal_distribution).
#include <cstdint>
#include <string>
#include <vector>

#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/localize/path_loss.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/localize/walls.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct ScenarioParams {
  std::uint64_t seed = 1;
  PathLossParams path_loss;             ///< the true model (the estimators assume the defaults)
  double tx_offset_db = 0.0;            ///< true 1 m level minus the assumed one (-5: 5 dB weaker)
  double shadowing_db = 6.0;            ///< standard deviation of the shadowing [dB]
  double decorrelation_distance = 1.0;  ///< [m] along the path
  double wall_attenuation_db = 8.0;     ///< per wall crossed (interior wall); 0 disables walls
  double door_attenuation_db = 4.0;     ///< per closed door crossed
  double speed = 0.5;                   ///< robot speed [m/s]
  double scan_rate = 10.0;              ///< RSSI readings per second [Hz]
  double position_noise = 0.05;         ///< standard deviation of the logged x and y [m]
  double antenna_height = 0.4;          ///< robot antenna height [m]
  double emitter_height = 1.0;          ///< phone height [m]
  double sensitivity_dbm = -90.0;       ///< the radio reports nothing weaker: the log's floor [dBm]
};

struct Scenario {
  std::string name;
  std::string description;
  RssiLog log;
  std::vector<EmitterTruth> truth;
  std::vector<WallSegment> walls;
  std::vector<model::Vec3> path;  ///< the robot's true waypoints [m]
};

/// loop, corner, room, hallway.
const std::vector<std::string>& scenario_names();

/// Throws InputError (field "--scenario") for an unknown name.
Scenario make_scenario(const std::string& name, const ScenarioParams& params = {});

}  // namespace rigdesign::localize
