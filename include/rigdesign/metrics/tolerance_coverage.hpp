#pragma once
/// Mounting tolerance (issue 38, item 1): each requirement sector's SC when the mounts sit
/// anywhere in their tolerance boxes (model::PoseTolerance), and the margin that survives. Each
/// mount's box is first tried one mount at a time, the others nominal: its corners (every
/// error axis at -w or +w) and face centres (one axis at -w or +w, the others 0), on the exact
/// path at every sampled azimuth of the sectors. Then, per sector and share, every mount at
/// once at the sample that was its own worst (errors of several mounts can open one gap
/// together). Where SC is monotone in each error (a camera's floor edge moving out as it
/// pitches up and rises) the worst case lies at a corner and this is the exact worst case;
/// otherwise it is the worst of these samples, and interior points may be worse: the
/// brute-force test (tests/metrics/tolerance_sampling_test.cpp) measures that gap on bundled
/// rigs, docs/tolerance.md gives it.
#include <string>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/work_budget.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

/// One error of a mount's pose: moved by `xyz` in the robot frame [m], turned by `rpy` about
/// the sensor's own axes [rad].
struct PoseError {
  model::Vec3 xyz = model::Vec3::Zero();
  model::Vec3 rpy = model::Vec3::Zero();
  /// The mode's FOV at its datasheet narrowest (SensorMode::narrowest): with a tolerance
  /// stated, every pose of a mount whose mode has a spread is judged so, a narrower FOV seeing
  /// a subset of a wider one's directions.
  bool narrowest_fov = false;
};

/// The errors tried for a tolerance box: 2^k corners and 2k face centres of its k axes with a
/// half-width above 0 (the two coincide for k = 1), in a fixed order.
std::vector<PoseError> tolerance_samples(const model::PoseTolerance& tolerance);

/// The errors tried for a mount with `tolerance` whose mode is `mode`: the box's samples, all
/// at the narrowest FOV when the mode has a spread (then the nominal pose too). Empty when
/// neither the box nor the FOV varies.
std::vector<PoseError> mount_error_samples(const model::PoseTolerance& tolerance,
                                           const model::SensorMode& mode);

/// `nominal` with `error` applied.
model::Pose3 with_error(const model::Pose3& nominal, const PoseError& error);

/// A mount's pose error.
struct MountError {
  std::string mount_id;
  PoseError error;
};

/// The worst share found and the errors that give it (none: the nominal rig is the worst).
struct WorstShare {
  double share = 0.0;  ///< judged_share of the sector's minimum over its azimuths
  std::vector<MountError> errors;
};

struct SectorTolerance {
  model::SectorRequirement sector;
  double nominal_complete = 0.0;  ///< the sector's SC complete minimum, every mount nominal
  double nominal_floor = 0.0;
  WorstShare complete;  ///< the smallest SC complete minimum over every mount's samples
  WorstShare floor;
  /// The requirement still met at the worst case (judged_share >= required, both shares).
  bool pass = false;

  /// The margin that survives: the smaller of worst complete - required and worst floor -
  /// required [share]; negative when the tolerance breaks the sector.
  double margin() const;
  /// Whether the floor share decides margin() (else SC complete).
  bool floor_binds() const;
};

/// Every sector of `sectors` over the tolerance boxes of the rig's mounts (rig.tolerance_for).
/// Empty when no mount has a tolerance. Precondition as compute_coverage; `settings.step` and
/// `settings.tessellation` are used, the exact path always. `budget`, when given, hears of
/// every moved pose judged and stops the work (InputError naming its option) once its time
/// is up.
std::vector<SectorTolerance> tolerance_coverage(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings = {},
    const WorkBudget* budget = nullptr);

/// SC margin against one rotation error of one mount (issue 38: "a plot of SC margin against
/// pitch/yaw error per mount"): the mount alone turned by each error, the others nominal,
/// exact path at the sectors' sampled azimuths.
struct ErrorSweep {
  std::string mount_id;
  int axis = 1;                  ///< 0 roll, 1 pitch, 2 yaw (about the sensor's own axes)
  double half_width = 0.0;       ///< [rad] the mount's tolerance about that axis
  std::vector<double> errors;    ///< [rad] from -3 to +3 half-widths
  std::vector<double> smallest;  ///< the smallest margin over the sectors at each [share]
  /// Each sector's margin at each error: min(complete - required, floor - required).
  std::vector<std::pair<std::string, std::vector<double>>> sectors;
};

/// Pitch and yaw sweeps of every mount with a non-zero pitch or yaw tolerance, `steps` errors
/// each (odd: the nominal pose is one). Empty without sectors or such tolerances.
std::vector<ErrorSweep> tolerance_sweeps(const model::Rig& rig, const model::SensorLibrary& library,
                                         const std::vector<model::SectorRequirement>& sectors,
                                         const CoverageSettings& settings = {}, int steps = 13);

}  // namespace rigdesign::metrics
