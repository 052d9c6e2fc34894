#include "rigdesign/io/config/urdf_poses.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <fstream>
#include <sstream>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

model::Pose3 to_pose(const urdf::Pose& pose) {
  model::Pose3 result = model::Pose3::Identity();
  result.translation() = model::Vec3(pose.position.x, pose.position.y, pose.position.z);
  result.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return result;
}

// T_root_link, by composing joint origins from the link up to the root.
model::Pose3 pose_in_root(const urdf::LinkConstSharedPtr& link) {
  model::Pose3 T_root_link = model::Pose3::Identity();
  for (urdf::LinkConstSharedPtr current = link; current && current->parent_joint;
       current = current->getParent()) {
    T_root_link = to_pose(current->parent_joint->parent_to_joint_origin_transform) * T_root_link;
  }
  return T_root_link;
}

}  // namespace

UrdfPoses UrdfPoses::load(const std::string& path, const std::string& base_link,
                          const model::SourceLocation& named_at,
                          const model::SourceLocation& base_named_at) {
  std::ifstream stream(path);
  if (!stream) {
    throw model::InputError(model::Diagnostic{named_at, "urdf.file",
                                              "names '" + path + "', which cannot be read",
                                              "a URDF file path relative to the rig file"});
  }
  std::stringstream xml;
  xml << stream.rdbuf();
  // urdfdom reports parse errors on the console itself; ours carries the file and line.
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml.str());
  if (!model) {
    throw model::InputError(
        model::Diagnostic{named_at, "urdf.file", "'" + path + "' is not a valid URDF",
                          "a URDF robot description (XML with <robot>, <link>, <joint>)"});
  }
  UrdfPoses poses;
  std::vector<urdf::LinkSharedPtr> links;
  model->getLinks(links);
  for (const urdf::LinkSharedPtr& link : links) poses.T_root_[link->name] = pose_in_root(link);
  poses.base_link_ = base_link.empty() ? model->getRoot()->name : base_link;
  if (poses.T_root_.count(poses.base_link_) == 0) {
    std::string names;
    for (const auto& [name, pose] : poses.T_root_) names += (names.empty() ? "" : ", ") + name;
    throw model::InputError(model::Diagnostic{base_named_at, "urdf.base_link",
                                              "no link '" + poses.base_link_ + "' in " + path,
                                              "one of: " + names});
  }
  return poses;
}

std::optional<model::Pose3> UrdfPoses::T_base(const std::string& link) const {
  const auto it = T_root_.find(link);
  if (it == T_root_.end()) return std::nullopt;
  return T_root_.at(base_link_).inverse() * it->second;
}

std::vector<std::string> UrdfPoses::link_names() const {
  std::vector<std::string> names;
  for (const auto& [name, pose] : T_root_) names.push_back(name);
  return names;
}

}  // namespace rigdesign::io
