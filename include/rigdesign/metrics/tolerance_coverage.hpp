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
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

/// One error of a mount's pose: moved by `xyz` in the robot frame [m], turned by `rpy` about
/// the sensor's own axes [rad].
struct PoseError {
  model::Vec3 xyz = model::Vec3::Zero();
  model::Vec3 rpy = model::Vec3::Zero();
};

/// The errors tried for a tolerance box: 2^k corners and 2k face centres of its k axes with a
/// half-width above 0 (the two coincide for k = 1), in a fixed order.
std::vector<PoseError> tolerance_samples(const model::PoseTolerance& tolerance);

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
/// `settings.tessellation` are used, the exact path always.
std::vector<SectorTolerance> tolerance_coverage(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings = {});

}  // namespace rigdesign::metrics
