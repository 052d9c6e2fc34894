#pragma once
/// Calibrating paper 4's path-loss model on a log whose emitter position is known: the level
/// at 1 m and the exponent of rssi = a - 10 n log10(d) + e, e ~ N(0, sigma^2), by maximum
/// likelihood over every scan: a heard one by its density, an unheard one as "below the
/// receiver's floor" (Tobit). Paper 4 calibrated per environment ("on previous runs in that
/// building"); its fitting procedure is not in the project's sources, so this is the textbook
/// fit (Rappaport, Wireless Communications, 2nd ed., section 4.9: the exponent that best fits
/// measurements at known distances) with the floor's censoring modelled: a least-squares line
/// through the heard readings alone is biased flat, because far away only the strongest
/// readings are heard (on a loop 6-17 m round a phone with a -87 dBm floor it gave n = -0.15
/// for a true 3.09).
/// Presets of the exponent per environment come from paper 4's Table 4 (DESIGN.md section 9).
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/localize/scan_series.hpp"
#include "rigdesign/localize/walls.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct PathLossCalibration {
  double rssi_at_1m_dbm = 0.0;  ///< a [dBm]
  double exponent = 0.0;        ///< n
  double sigma_db = 0.0;        ///< of the scans about the model [dB]
  double level_sd_db = 0.0;     ///< standard error of a [dB] (inverse observed information)
  double exponent_sd = 0.0;     ///< standard error of n
  int heard = 0, unheard = 0;   ///< scans used
  double nearest_m = 0.0, farthest_m = 0.0;  ///< the distances they span
};

/// Scans closer than this to the emitter are left out: the log-distance law holds in the far
/// field, and there the antennas' height difference dominates [m].
inline constexpr double kCalibrationMinDistance = 1.0;

/// The maximum-likelihood level, exponent and sigma of `scans` for an emitter at `truth`
/// (distances in 3D), the loss of the mapped `walls` each scan's ray crosses taken off first.
/// Empty when fewer than 3 scans are heard or their log-distances do not vary (a circle round
/// the emitter tells no exponent).
std::optional<PathLossCalibration> calibrate_path_loss(const ScanSeries& scans,
                                                       const model::Vec3& truth,
                                                       const std::vector<WallSegment>& walls = {});

/// Why `fit` must not be suggested or used, empty when it may: a value that is not finite, a
/// level outside [-120, 30] dBm or an exponent outside [0.5, 10] (the ranges localize's
/// --rssi-at-1m and --exponent accept; measured exponents lie between 1.6 and 6, Rappaport
/// Table 4.2), or a sigma below 0.01 dB (readings on the model to a hundredth of a dB, where
/// receivers report whole dBm: the likelihood grows without bound as sigma falls, so its
/// "maximum" there is no fit).
std::string calibration_problem(const PathLossCalibration& fit);

/// A published exponent for a kind of environment (paper 4's Table 4, its reference [49], and
/// the thesis's underground stations; the midpoint where it gives a range).
struct EnvironmentPreset {
  std::string name;
  double exponent;
  std::string source;  ///< the table's row and range, quoted
};

const std::vector<EnvironmentPreset>& environment_presets();

/// The preset named `name`, or nullptr.
const EnvironmentPreset* find_environment_preset(const std::string& name);

}  // namespace rigdesign::localize
