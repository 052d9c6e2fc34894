#pragma once
/// Mounting tolerance (issue 38, item 1): each requirement sector's SC when a mount sits
/// anywhere in its tolerance box (model::PoseTolerance), and the margin that survives. The box
/// of each mount is tried one mount at a time, the others at their nominal poses: its corners
/// (every error axis at -w or +w) and face centres (one axis at -w or +w, the others 0), on
/// the exact path at every sampled azimuth of the sectors. Where SC is monotone in each error
/// (a camera's floor edge moving out as it pitches up and rises) the worst case lies at a
/// corner and this is the exact worst case; otherwise it is the worst of these samples.
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

/// The worst share found and the mount and error that give it.
struct WorstShare {
  double share = 0.0;  ///< judged_share of the sector's minimum over its azimuths
  std::string mount_id;
  PoseError error;
};

struct SectorTolerance {
  model::SectorRequirement sector;
  double nominal_complete = 0.0;  ///< the sector's SC complete minimum, every mount nominal
  double nominal_floor = 0.0;
  WorstShare complete;  ///< the smallest SC complete minimum over every mount's samples
  WorstShare floor;
  /// The requirement still met at the worst case (judged_share >= required, both shares).
  bool pass = false;
};

/// Every sector of `sectors` over the tolerance boxes of the rig's mounts (rig.tolerance_for).
/// Empty when no mount has a tolerance. Precondition as compute_coverage; `settings.step` and
/// `settings.tessellation` are used, the exact path always.
std::vector<SectorTolerance> tolerance_coverage(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const CoverageSettings& settings = {});

}  // namespace rigdesign::metrics
