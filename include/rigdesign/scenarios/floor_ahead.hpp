#pragma once
/// The closed-loop check of "see the floor ahead" (issue 35 item 4): how far ahead of the
/// robot, within its width, a mount sees the floor, and the speed from which the robot can
/// still stop for a drop first seen there.
#include <string>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/scenarios/sensor_timing.hpp"

namespace rigdesign::scenarios {

struct FloorAhead {
  /// The mount seeing the floor farthest ahead (empty: none sees it within the body's width).
  std::string mount;
  double distance = 0.0;  ///< [m] from the robot's centre, along +x
  /// [s] from a drop's edge entering view to the brakes: a frame period (it may appear just
  /// after a capture), the frame's latency, a costmap update period and a control period.
  double reaction = 0.0;
  double deceleration = 0.0;  ///< [m/s^2]
  /// [m/s] the highest speed from which the body's front stops short of the edge seen at
  /// `distance`: v reaction + v^2 / (2 a) = distance - body radius; 0 when none sees the floor.
  double stoppable_speed = 0.0;
};

/// Casts every ray of every mount's mode (no decimation) onto a flat floor at z = 0 and keeps
/// hits within the mode's range, ahead of the centre and within the body's radius of its
/// centre line. `timings` are the mounts' (rig order), `update_period` and `control_period`
/// the loop's [s], `deceleration` [m/s^2].
FloorAhead floor_ahead(const model::Rig& rig, const model::SensorLibrary& library,
                       const std::vector<MountTiming>& timings, double update_period,
                       double control_period, double deceleration);

/// v such that v t + v^2 / (2 a) = d (0 when d <= 0).
double stoppable_speed(double distance, double reaction, double deceleration);

}  // namespace rigdesign::scenarios
