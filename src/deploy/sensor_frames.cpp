#include "rigdesign/deploy/sensor_frames.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <vector>

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
  throw model::InputError(model::Diagnostic{model::SourceLocation{"(command line)"}, "--parent",
                                            "no link '" + parent + "' in " + rig.file,
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

namespace {

// The names a mount's frames take after its driver's defaults (or the rig's `ros: {frame}`).
struct DriverNames {
  std::string link;
  std::optional<std::string> optical;  // a camera's optical frame the URDF gives
  std::string data_frame;
  bool from_driver = false;  // the driver broadcasts data_frame itself
};

std::optional<DriverNames> driver_names(const model::Mount& mount, const model::Sensor& sensor,
                                        bool camera) {
  if (!mount.ros_frame.empty()) {
    if (camera) return DriverNames{sensor_link_name(mount.id), mount.ros_frame, mount.ros_frame};
    return DriverNames{mount.ros_frame, std::nullopt, mount.ros_frame};
  }
  if (!sensor.ros2 || !sensor.ros2->exists) return std::nullopt;
  const model::RosDriver& driver = *sensor.ros2;
  if (!driver.driver_frames.empty())
    return DriverNames{driver.driver_frames.front(), std::nullopt, driver.frame_id, true};
  if (camera) return DriverNames{sensor_link_name(mount.id), driver.frame_id, driver.frame_id};
  return DriverNames{driver.frame_id, std::nullopt, driver.frame_id};
}

// Where the link the export adds sits in the sensor frame: the sensor origin, except for a
// driver's root frame whose own transforms move the data frame (issue 52 item 4): that root is
// placed so that root * driver transforms = the designed data frame (the sensor frame, turned
// to REP-103's optical axes when the data frame is optical).
model::Pose3 T_sensor_link(const DriverNames& names, const model::Sensor& sensor) {
  if (!names.from_driver || !sensor.ros2 || !sensor.ros2->T_root_data)
    return model::Pose3::Identity();
  const model::Pose3 T_sensor_data =
      sensor.ros2->data_frame_optical ? model::T_sensor_optical() : model::Pose3::Identity();
  return T_sensor_data * sensor.ros2->T_root_data->inverse();
}

// What to set on the driver so that it stamps `frame`, or "" when it does by default.
std::string driver_note(const model::Sensor& sensor, const std::string& frame) {
  if (!sensor.ros2 || !sensor.ros2->exists || sensor.ros2->frame_id == frame) return "";
  return sensor.ros2->package + " stamps '" + sensor.ros2->frame_id + "' by default: set " +
         sensor.ros2->frame_parameter + " to '" + frame + "'";
}

}  // namespace

SensorFrames sensor_frames(const model::Rig& rig, const model::SensorLibrary& library,
                           const std::string& parent) {
  SensorFrames frames;
  frames.parent = parent.empty() ? rig.base_link : parent;
  const model::Pose3 T_parent_robot = T_robot_parent(rig, frames.parent).inverse();
  model::Diagnostics findings;
  AddedNames added(rig, findings);
  // The drivers' names for mounts placed by pose; a name two mounts would take, or the
  // description has, falls back to the mount's own (`ros: {frame}` names are kept: a clash
  // of those is the rig's error, reported below).
  std::vector<std::optional<DriverNames>> named(rig.mounts.size());
  std::map<std::string, int> uses;
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    if (!mount.urdf_link.empty() && rig.link_poses.count(mount.urdf_link)) continue;
    const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
    named[m] = driver_names(mount, *library.find(mount.sensor_id), mode.is_camera());
    if (named[m]) {
      ++uses[named[m]->link];
      if (named[m]->optical) ++uses[*named[m]->optical];
    }
  }
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    if (!named[m] || !mount.ros_frame.empty()) continue;
    const auto taken = [&](const std::string& name) {
      return uses[name] > 1 || rig.link_where.count(name) > 0;
    };
    if (taken(named[m]->link) || (named[m]->optical && taken(*named[m]->optical))) named[m].reset();
  }
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    const model::Sensor& sensor = *library.find(mount.sensor_id);
    const model::SensorMode* mode = &library.resolved_mode(mount.sensor_id, mount.mode_id);
    SensorFrame frame;
    frame.mount_id = mount.id;
    frame.sensor_id = mount.sensor_id;
    frame.mode_id = mount.mode_id;
    const bool on_link = !mount.urdf_link.empty() && rig.link_poses.count(mount.urdf_link);
    frame.link = on_link ? mount.urdf_link : named[m] ? named[m]->link : sensor_link_name(mount.id);
    if (!on_link) frame.joint = mount.id + "_joint";
    if (named[m]) {
      if (named[m]->optical) {
        frame.optical_frame = named[m]->optical;
        frame.optical_joint = mount.id + "_optical_joint";
      }
      frame.data_frame = named[m]->data_frame;
      frame.data_frame_from_driver = named[m]->from_driver;
    } else {
      if (mode->is_camera()) {
        if (on_link && mount.urdf_link_optical) {
          frame.optical_frame = mount.urdf_link;
        } else if (const auto child =
                       on_link ? optical_child(rig, mount.urdf_link) : std::nullopt) {
          frame.optical_frame = *child;
        } else {
          frame.optical_frame = optical_frame_name(mount.id);
          frame.optical_joint = mount.id + "_optical_joint";
        }
      }
      frame.data_frame = frame.optical_frame.value_or(frame.link);
      frame.note = driver_note(sensor, frame.data_frame);
    }
    // A link taken as the optical frame stands at the optical pose; its joint is not written.
    const model::Pose3 T_sensor_added =
        named[m] ? T_sensor_link(*named[m], sensor) : model::Pose3::Identity();
    frame.T_parent_link = T_parent_robot * mount.T_robot_sensor * T_sensor_added;
    frame.T_link_sensor = T_sensor_added.inverse();
    if (frame.data_frame_from_driver)
      frame.T_link_data = sensor.ros2->T_root_data.value_or(model::T_sensor_optical());
    // The datasheet housing on the link the export adds (a description's link has its own).
    if (!on_link && sensor.housing) {
      frame.housing = sensor.housing;
      frame.T_link_housing =
          T_sensor_added.inverse() * Eigen::Translation3d(sensor.housing->center);
    }
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
