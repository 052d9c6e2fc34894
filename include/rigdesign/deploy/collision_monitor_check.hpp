#pragma once
/// `check --collision-monitor` (issue 34): a deployed nav2 collision monitor protects the robot
/// only where its sources see its zones. Result D4 per enabled zone: every point of its edge
/// outside the robot is seen by one of the zone's sources (its sources_names, else every
/// source) on the column from the floor to the top of the area to perceive, within the heights
/// that source passes (deploy/zone_visibility.hpp); on failure the unseen arcs and the zone's
/// `points` setting with file:line.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

/// One polygon of the file, in its base frame.
struct DeployedZone {
  std::string name;
  std::string type;    ///< polygon, circle or velocity_polygon
  std::string action;  ///< stop, slowdown, limit, approach or none
  bool enabled = true;
  std::vector<model::Vec2> points;  ///< [m] a polygon's corners, or a circle's as a polygon
  /// The zone's sources by name; nothing: every observation source (nav2's default).
  std::optional<std::vector<std::string>> sources_names;
  model::SourceLocation where;         ///< the polygon's map
  model::SourceLocation points_where;  ///< its points (or radius)
};

/// One observation source of the file, matched to a mount of the rig.
struct DeployedMonitorSource {
  std::string name;
  std::string mount_id;  ///< empty for a source type rigdesign does not model (range, polygon)
  std::string type;      ///< scan, pointcloud, range or polygon
  bool enabled = true;
  /// [m] a pointcloud's height band in the base frame (nav2's defaults 0.05 and 0.5).
  double min_height = 0.05;
  double max_height = 0.5;
  double min_range = 0.0;  ///< [m] Jazzy's pointcloud min_range
  model::SourceLocation where;
};

struct DeployedCollisionMonitor {
  std::string file;
  std::string base_frame = "base_footprint";  ///< nav2's default base_frame_id
  std::vector<DeployedZone> zones;
  std::vector<DeployedMonitorSource> sources;
  std::vector<model::Diagnostic> warnings;  ///< what the file holds that is not checked
};

/// D4 results, one per enabled zone with an area (approach zones follow the footprint and
/// are skipped, as are zones of action none). Precondition: the rig's references resolve.
/// Throws InputError at the file's base_frame_id when it is neither base_footprint nor a link
/// of the rig's description.
std::vector<metrics::RequirementResult> check_collision_monitor(
    const model::Rig& rig, const model::SensorLibrary& library,
    const DeployedCollisionMonitor& monitor);

}  // namespace rigdesign::deploy
