#include "rigdesign/deploy/sensor_frames.hpp"

#include <cmath>
#include <map>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/optical_frame.hpp"

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

std::string sensor_link_name(const std::string& mount_id) {
  return mount_id + "_link";
}

std::string optical_frame_name(const std::string& mount_id) {
  return mount_id + "_optical_frame";
}

namespace {

// [m], [rad] a description's child link this close to the optical pose of its parent is the
// camera's optical frame.
constexpr double kSameFrame = 1e-6;

// The description's child of `link` at `link`'s optical pose (z forward), if any.
std::optional<std::string> optical_child(const model::Rig& rig, const std::string& link) {
  const model::Pose3 wanted = rig.link_poses.at(link) * model::T_sensor_optical();
  for (const auto& [child, parent] : rig.parent_link) {
    if (parent != link) continue;
    const model::Pose3& pose = rig.link_poses.at(child);
    const Eigen::AngleAxisd turn(wanted.linear().transpose() * pose.linear());
    if ((pose.translation() - wanted.translation()).norm() <= kSameFrame &&
        std::abs(turn.angle()) <= kSameFrame) {
      return child;
    }
  }
  return std::nullopt;
}

// The names the export adds, each with the mount that adds it: checked against the
// description's links and joints and against each other.
class AddedNames {
 public:
  AddedNames(const model::Rig& rig, model::Diagnostics& findings)
      : rig_(rig), findings_(findings) {}

  void add(const model::Mount& mount, const std::string& name, bool is_link) {
    if (name.empty()) return;
    const auto& taken = is_link ? rig_.link_where : rig_.joint_where;
    const std::string kind = is_link ? "link" : "joint";
    if (const auto it = taken.find(name); it != taken.end()) {
      findings_.error(mount.where, "mounts." + mount.id,
                      "would add the " + kind + " '" + name + "', which the robot description " +
                          "already has at " + model::to_string(it->second),
                      "a mount id whose frames are new names, or `pose: {urdf_link: " + name +
                          "}` to use the description's link");
      return;
    }
    const auto [it, added] = added_.emplace(kind + " " + name, &mount);
    if (!added) {
      findings_.error(mount.where, "mounts." + mount.id,
                      "would add the " + kind + " '" + name + "', which mount '" + it->second->id +
                          "' (" + model::to_string(it->second->where) + ") adds too",
                      "mount ids whose frame names differ (" + kind + "s are <id>_link, " +
                          "<id>_joint, <id>_optical_frame, <id>_optical_joint)");
    }
  }

 private:
  const model::Rig& rig_;
  model::Diagnostics& findings_;
  std::map<std::string, const model::Mount*> added_;
};

}  // namespace

SensorFrames sensor_frames(const model::Rig& rig, const model::SensorLibrary& library,
                           const std::string& parent) {
  SensorFrames frames;
  frames.parent = parent.empty() ? rig.base_link : parent;
  const model::Pose3 T_parent_robot = T_robot_parent(rig, frames.parent).inverse();
  model::Diagnostics findings;
  AddedNames added(rig, findings);
  for (const model::Mount& mount : rig.mounts) {
    const model::SensorMode* mode = &library.resolved_mode(mount.sensor_id, mount.mode_id);
    SensorFrame frame;
    frame.mount_id = mount.id;
    frame.sensor_id = mount.sensor_id;
    frame.mode_id = mount.mode_id;
    const bool on_link = !mount.urdf_link.empty() && rig.link_poses.count(mount.urdf_link);
    frame.link = on_link ? mount.urdf_link : sensor_link_name(mount.id);
    if (!on_link) frame.joint = mount.id + "_joint";
    if (mode->is_camera()) {
      if (on_link && mount.urdf_link_optical) {
        frame.optical_frame = mount.urdf_link;
      } else if (const auto child = on_link ? optical_child(rig, mount.urdf_link) : std::nullopt) {
        frame.optical_frame = *child;
      } else {
        frame.optical_frame = optical_frame_name(mount.id);
        frame.optical_joint = mount.id + "_optical_joint";
      }
    }
    frame.data_frame = frame.optical_frame.value_or(frame.link);
    // A link taken as the optical frame stands at the optical pose; its joint is not written.
    frame.T_parent_link = T_parent_robot * mount.T_robot_sensor;
    if (!on_link) added.add(mount, frame.link, true);
    added.add(mount, frame.joint, false);
    if (!frame.optical_joint.empty()) added.add(mount, *frame.optical_frame, true);
    added.add(mount, frame.optical_joint, false);
    frames.frames.push_back(std::move(frame));
  }
  findings.throw_if_errors();
  return frames;
}

}  // namespace rigdesign::deploy
