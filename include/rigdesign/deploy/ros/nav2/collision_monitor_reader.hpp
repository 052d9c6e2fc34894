#pragma once
/// A nav2 collision_monitor parameter file, for `check --collision-monitor` (issue 34): the
/// `collision_monitor: ros__parameters:` block (or the same keys at the top of the file), with
/// nav2's key names and both releases' spellings of a polygon (Jazzy's string
/// "[[x, y], ...]", Humble's flat list of numbers; a circle's radius). Keys nav2 declares that
/// rigdesign does not model (topics of the velocity command, timeouts, visualisation) are
/// read past (data/ros_parameters/nav2_collision_monitor.yaml); any other key is an error.
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/deploy/collision_monitor_check.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::deploy {

/// A mount's topic and id: a source that is not named after a mount is matched by its topic.
using MountTopic = std::pair<std::string, std::string>;

/// Throws InputError naming file:line:col, the key's path and the expected form for a missing
/// file, a malformed value, an unknown key, a polygon or source named but not given, a
/// sources_names entry that is no source, or a scan/pointcloud source that matches no mount
/// (by name or by one of `mount_topics`).
deploy::DeployedCollisionMonitor load_collision_monitor(
    const std::string& path, const model::Rig& rig, const std::vector<MountTopic>& mount_topics);

}  // namespace rigdesign::deploy
