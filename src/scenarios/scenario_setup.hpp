#pragma once
// What a scenario run derives from the rig before it starts: the costmap and source settings
// fitted to the body, and each mount's (decimated) ray pattern. Private to scenarios.
#include <vector>

#include "rigdesign/scenarios/scenario_runner.hpp"

namespace rigdesign::scenarios::detail {

struct SimulatedMount {
  model::Mount mount;
  model::SensorMode mode;             ///< the mount's mode with the decimated angular steps
  std::vector<model::Vec3> rays;      ///< ray_pattern(mode), sensor frame
  costmap::ObservationSource source;  ///< what its clouds mark and clear (mount_sources_of)
  MountTiming timing;                 ///< when its frames are captured and arrive
  /// Per ray, where the robot itself hides it (sim::robot_free_ranges): the body, the other
  /// mounts' housings and the supports stop rays in the loop as they do in the coverage report.
  std::vector<double> free_ranges;
};

struct Setup {
  costmap::CostmapParams costmap;
  std::vector<SimulatedMount> mounts;
};

/// Fits the parameters to the rig's body (see ScenarioParams) and builds the ray patterns.
/// Mounts whose sensor or mode the library lacks are skipped (check_scenario_inputs reports them).
Setup make_setup(const model::Rig& rig, const model::SensorLibrary& library,
                 const ScenarioParams& params);

/// The robot frame on the floor at a planar pose.
model::Pose3 to_pose3(const costmap::Pose2& pose);

/// Whether any ray of `mount`, with the robot at the origin, reaches the source's height band
/// within the range where its end points would mark.
bool can_mark(const SimulatedMount& mount, const costmap::ObservationSource& source);

}  // namespace rigdesign::scenarios::detail
