#pragma once
/// Gas-source detection from a CO2 log as paper 4's ground robot does it (DESIGN.md section
/// 8): a detection at the first reading over the threshold (1800 ppm; the rules' 2000 ppm), at
/// most one detection per 5 m. Two options that are not the thesis's ground-robot method: a
/// trailing moving average (the thesis's 5 samples are for its UAVs) and reporting the
/// strongest reading in the detection's area instead of the first (the thesis's future work).
/// Two additions: a threshold relative to a running baseline (median + k MAD of the readings
/// before, for sensors and sites whose ambient level is far from a fixed threshold), and a
/// lag correction that moves a detection back along the path by the sensor's delay.
#include <cstddef>
#include <string>
#include <vector>

#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

enum class GasThreshold { fixed, relative };

struct GasDetectionParams {
  /// Readings averaged (trailing). 1: each reading on its own, as paper 4's ground robot; the
  /// thesis's 5-sample average is for its UAVs (`--moving-average 5`).
  int moving_average = 1;
  double fixed_threshold_ppm = 1800;  ///< paper 4 (the SubT rule: 2000 ppm)
  double spacing = 5.0;               ///< one detection per this distance [m] (paper 4)
  /// Report the strongest reading in the detection's area instead of the first: the thesis's
  /// future work, not its method (`--refine-strongest`).
  bool refine_strongest = false;
  int baseline_window = 60;    ///< readings in the running baseline (relative mode)
  int min_baseline = 10;       ///< readings needed before the relative mode detects
  double mad_factor = 6.0;     ///< k in median + k * 1.4826 MAD
  double min_rise_ppm = 50.0;  ///< the relative threshold is at least this above the median
  /// Sensor time constant [s]: an NDIR CO2 sensor reads a step with a first-order lag, which
  /// reaches 63 % of a step after one time constant and trails a ramp by it. Paper 4's
  /// sensor, the Sensirion SCD30, responds to a rising edge in 20 s (paper 4; the SCD30
  /// datasheet, v1.0 May 2020, section 1: response time tau63 = 20 s).
  double time_constant = 20.0;
  double sample_period = 1.0;  ///< [s] between readings of an untimed log (assumed)
};

struct GasDetection {
  std::size_t trigger_index = 0;  ///< reading (or moving average) first over the threshold
  std::size_t index = 0;          ///< reading reported (the strongest in the area when refining)
  model::Vec3 position = model::Vec3::Zero();  ///< robot position at `index` [m]
  model::Vec3 lag_corrected =
      model::Vec3::Zero();     ///< the path position the lag says the air came from [m]
  double ppm = 0.0;            ///< reading (or moving average) at `index`
  double threshold_ppm = 0.0;  ///< threshold in force at the trigger
};

/// Detections in reading order: one where a reading (or moving average) is over the threshold
/// and no earlier detection lies within `spacing`; readings within `spacing` of its trigger
/// belong to it.
std::vector<GasDetection> detect_gas(const Co2Log& log, GasThreshold threshold,
                                     const GasDetectionParams& params = {});

/// The delay between the air at a place and its reading [s]: the sensor's time constant plus
/// the trailing moving average's half width (none for single readings).
double detection_lag(const Co2Log& log, const GasDetectionParams& params);

struct GasArtifactResult {
  Artifact artifact;
  double path_distance = 0.0;      ///< closest approach of the robot's path [m]
  double nearest_detection = 0.0;  ///< distance to the nearest detection (infinite if none) [m]
  bool found = false;              ///< a detection within the scoring radius
};

struct GasScore {
  std::vector<GasArtifactResult> artifacts;  ///< the `gas` artifacts
  int true_detections = 0;                   ///< detections within the radius of a gas artifact
  int false_detections = 0;
};

/// Scores detections against the `gas` artifacts: horizontal distance (an untimed trace has
/// no z), within `radius` (DARPA: 5 m). `lag_corrected` picks which position is scored.
GasScore score_gas(const Co2Log& log, const std::vector<GasDetection>& detections,
                   const std::vector<Artifact>& artifacts, bool lag_corrected, double radius = 5.0);

}  // namespace rigdesign::localize
