#pragma once
/// The frames a rig's sensors need in the robot's description (issues 14 and 30): a mount
/// placed on a description's link (`urdf_link`) uses that link as it is; any other mount gets
/// a link at the sensor origin with a fixed joint to a parent link, named after the mount id.
/// Lidar and scanner links keep REP-103's body axes (x forward, z up), which is how their
/// drivers stamp scans and clouds; a camera gets an optical frame (z forward, x right, y
/// down) for the images and depth clouds its driver publishes: the link itself when it is
/// one, the description's optical child of its link when that has one, else a new
/// `<id>_optical_frame`. A name the export would add that the description already has (or
/// that two mounts would both add) is an error naming both places. Names follow the sensor's
/// ROS 2 driver (sensors.yaml `ros2`) where the rig keeps them unique: a lidar's link is the
/// frame its driver stamps (velodyne, laser), a sensor whose driver broadcasts its own frames
/// gets only their root (camera_link, os_sensor), placed so that the driver's own static
/// transforms (sensors.yaml `ros2.data_frame_pose`) put the data frame at the designed pose; a
/// mount's `ros: {frame}` names the frame outright; otherwise `<id>_link` and a note saying which
/// driver parameter to set.
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
  std::string link;  ///< the description's `urdf_link`, or `<id>_link`
  /// The export adds `link` with this fixed joint from the parent; empty when the description
  /// has the link (a mount placed by `urdf_link`).
  std::string joint;
  /// A camera's optical frame (nothing for lidars and scanners), and the joint the export adds
  /// for it from `link` (empty when the description has the frame).
  std::optional<std::string> optical_frame;
  std::string optical_joint;
  std::string data_frame;  ///< what the driver stamps with: the optical frame, else the link
  /// The driver broadcasts data_frame itself (below `link`, which the export places so that
  /// the data frame lands on the designed pose): e.g. realsense2_camera's camera_link ->
  /// camera_depth_optical_frame, ouster_ros's os_sensor -> os_lidar (36 mm up, turned 180 deg).
  bool data_frame_from_driver = false;
  std::string note;  ///< what to set on the driver so it stamps data_frame, if anything
  model::Pose3 T_parent_link = model::Pose3::Identity();  ///< the fixed joint's origin
  /// The sensor (its designed pose, body axes) in `link`: identity but for a driver's root
  /// placed so that its own transforms reach the designed data frame (issue 52 item 4).
  model::Pose3 T_link_sensor = model::Pose3::Identity();
  /// With data_frame_from_driver: the driver's data frame in `link` (sensors.yaml
  /// `ros2.data_frame_pose`), which a simulation without the driver must add itself.
  model::Pose3 T_link_data = model::Pose3::Identity();
  /// The sensor's datasheet housing (issue 52 item 2), drawn and collided on the added link
  /// so RViz and self-filters see it; its centre's pose in that link. Nothing for a mount on
  /// the description's own link, or a sensor without one.
  std::optional<model::HousingSolid> housing;
  model::Pose3 T_link_housing = model::Pose3::Identity();
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

/// Frames of every mount of `rig` (modes from `library`; a mount whose mode is missing is a
/// precondition violation). `parent` empty: the rig's base link (base_footprint without a
/// description). Throws InputError at the rig when `parent` is neither base_footprint nor a
/// link of the rig's description, and at a mount whose added link or joint the description
/// already has (naming its file and line) or another mount adds too.
SensorFrames sensor_frames(const model::Rig& rig, const model::SensorLibrary& library,
                           const std::string& parent = {});

}  // namespace rigdesign::deploy
