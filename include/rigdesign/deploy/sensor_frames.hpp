#pragma once
/// The frames a rig's sensors need in the robot's description (issue 14): per mount a link at
/// the sensor origin with a fixed joint to a parent link, named after the mount id. Lidar and
/// scanner links keep REP-103's body axes (x forward, z up), which is how their drivers stamp
/// scans and clouds; a camera link gets an `_optical_frame` child (z forward, x right, y down)
/// for the images and depth clouds its driver publishes.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

struct SensorFrame {
  std::string mount_id;
  std::string sensor_id;
  std::string mode_id;
  std::string link;                          ///< `<id>_link`
  std::optional<std::string> optical_frame;  ///< `<id>_optical_frame` for cameras
  model::Pose3 T_parent_link = model::Pose3::Identity();  ///< the fixed joint's origin
};

struct SensorFrames {
  std::string parent;  ///< every joint's parent link
  std::vector<SensorFrame> frames;
};

/// The link name of a mount's sensor, and a camera's optical frame.
std::string sensor_link_name(const std::string& mount_id);
std::string optical_frame_name(const std::string& mount_id);

/// A frame's pose in the robot frame: base_footprint (the robot frame itself, REP-105) or a
/// link of the rig's description; nothing for any other name.
std::optional<model::Pose3> robot_frame_pose(const model::Rig& rig, const std::string& frame);

/// The frame a mount's driver stamps its data with: a camera's optical frame, else its link.
std::string data_frame_name(const std::string& mount_id, const model::SensorMode& mode);

/// Frames of every mount of `rig` (modes from `library`; a mount whose mode is missing is a
/// precondition violation). `parent` empty: the rig's base link (base_footprint without a
/// description). Throws InputError at the rig when `parent` is neither base_footprint nor a
/// link of the rig's description.
SensorFrames sensor_frames(const model::Rig& rig, const model::SensorLibrary& library,
                           const std::string& parent = {});

}  // namespace rigdesign::deploy
