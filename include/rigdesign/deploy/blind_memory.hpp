#pragma once
/// Paper 1's Hit Layer sized from the rig's own blind sectors (issue 14 item 3). A blind gap
/// is a run of azimuths where the rig sees none of the floor between the body and the
/// distance of interest (SC floor = 0): a cable or a foot there is invisible (for a rig that
/// sees no floor anywhere, level scan planes, where it sees nothing: SC complete = 0). The rule,
/// for a robot driving straight past a static obstacle that grazes its side (lateral offset r, the
/// body's radius at the gap's edge):
/// - it is seen while its azimuth runs through the covered azimuths before the gap, from the
///   distance of interest d (x = sqrt(d^2 - r^2)) or the start of that covered run, down to
///   the gap's first azimuth a1 (x = r cot a1): the seen distance;
/// - it must be kept while its azimuth runs through the gap, to a2 (x = r cot a2), or, when
///   the gap reaches the back and it is never seen again, until the body has passed it
///   (x = -r): the keep distance;
/// - the Hit Layer loses 1 per update while the robot moves, however slowly, so the count
///   must outlast the keep distance driven at the slowest speed, twice over (margin for a
///   robot that turns or stops inside the gap): hit_max = ceil(2 f keep / v_min);
/// - and it must reach hit_max while the obstacle is seen at the fastest speed:
///   hit = ceil(hit_max / (f seen / v_max)), f the costmap's update rate.
/// The gap with the largest keep distance sets hit_max and, with its seen distance, hit.
///
/// nav2 itself keeps an obstacle by time, not by motion: a source's observation_persistence
/// keeps each of its clouds marking for that many seconds. The same keep, in seconds, is
/// hit_max / f (twice the time to drive the keep distance at the slowest speed), given to the
/// sources that see an obstacle one cell outside the body on its approach to the gap, from the
/// distance of interest to where it is seen last (BlindGap::last_seen; deploy/costmap_config).
/// What it assumes: the robot does not stand still with an obstacle in the gap
/// for longer than that (the Hit Layer does not decay while the robot stands; persistence
/// does), and a person walking through those sources' view leaves a trail for that long.
#include <string>
#include <vector>

#include "rigdesign/costmap/hit_layer.hpp"
#include "rigdesign/metrics/coverage.hpp"

namespace rigdesign::deploy {

struct BlindGap {
  double from = 0.0;           ///< [rad] first blind azimuth, counter-clockwise from forward
  double to = 0.0;             ///< [rad] last blind azimuth (to >= from; may exceed pi)
  double keep_distance = 0.0;  ///< [m] driven while a grazing obstacle is in the gap
  double seen_distance = 0.0;  ///< [m] driven while it is seen before the gap
  bool reaches_back = false;   ///< an obstacle passing it is not seen again
  /// Index into the coverage's angles where a grazing obstacle is seen last before it enters
  /// the gap (on the side of the longest pass); -1 when it is not seen before the gap.
  int last_seen = -1;
  double persistence = 0.0;  ///< [s] how long a source seeing `last_seen` must keep a cloud
};

struct BlindMemory {
  std::vector<BlindGap> gaps;
  int worst_gap = -1;           ///< index of the gap with the largest keep distance; -1: no gap
  double max_speed = 0.0;       ///< [m/s]
  double min_speed = 0.0;       ///< [m/s] the slowest the robot drives
  double update_rate = 0.0;     ///< [Hz]
  costmap::HitLayerParams hit;  ///< paper 1's values where there is no gap
  double persistence = 0.0;     ///< [s] the worst gap's; 0 where there is no gap
  std::string rule;             ///< one sentence with the numbers, for reports and comments
};

/// From `coverage` of the rig (its angles, body radius per angle and distance). Precondition:
/// 0 < min_speed <= max_speed, update_rate > 0.
BlindMemory blind_memory(const metrics::RigCoverage& coverage, double max_speed, double min_speed,
                         double update_rate);

}  // namespace rigdesign::deploy
