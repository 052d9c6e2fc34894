#include "rigdesign/deploy/sensor_frames.hpp"


#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::deploy {
namespace {

// The robot frame's pose of `parent`, or an InputError naming the frames there are.
model::Pose3 T_robot_parent(const model::Rig& rig, const std::string& parent) {
  if (const std::optional<model::Pose3> pose = robot_frame_pose(rig, parent)) return *pose;
  std::vector<std::string> names = {"base_footprint"};
  for (const auto& [name, pose] : rig.link_poses) names.push_back(name);
  throw model::InputError(model::Diagnostic{
      model::SourceLocation{"(command line)"}, "--parent", "no link '" + parent + "' in " + rig.file,
      "one of: " + model::join(names)});
}

}  // namespace

std::optional<model::Pose3> robot_frame_pose(const model::Rig& rig, const std::string& frame) {
  if (const auto link = rig.link_poses.find(frame); link != rig.link_poses.end()) {
    return link->second;
  }
  if (frame == "base_footprint") return model::Pose3::Identity();
  return std::nullopt;
}

std::string data_frame_name(const std::string& mount_id, const model::SensorMode& mode) {
  return mode.is_camera() ? optical_frame_name(mount_id) : sensor_link_name(mount_id);
}

std::string sensor_link_name(const std::string& mount_id) {
  return mount_id + "_link";
}

std::string optical_frame_name(const std::string& mount_id) {
  return mount_id + "_optical_frame";
}

SensorFrames sensor_frames(const model::Rig& rig, const model::SensorLibrary& library,
                           const std::string& parent) {
  SensorFrames frames;
  frames.parent = parent.empty() ? rig.base_link : parent;
  const model::Pose3 T_parent_robot = T_robot_parent(rig, frames.parent).inverse();
  for (const model::Mount& mount : rig.mounts) {
    const model::SensorMode* mode = &library.resolved_mode(mount.sensor_id, mount.mode_id);
    SensorFrame frame;
    frame.mount_id = mount.id;
    frame.sensor_id = mount.sensor_id;
    frame.mode_id = mount.mode_id;
    frame.link = sensor_link_name(mount.id);
    if (mode->is_camera()) frame.optical_frame = optical_frame_name(mount.id);
    frame.T_parent_link = T_parent_robot * mount.T_robot_sensor;
    frames.frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace rigdesign::deploy
