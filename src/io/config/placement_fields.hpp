#pragma once
// Fields that rig files and candidate catalogs share: the robot body, the optional URDF and
// sensor poses (xyz + rpy_deg, or a URDF link). Private to io.
#include <optional>
#include <string>

#include "io/config/yaml_reader.hpp"
#include "rigdesign/io/config/urdf_poses.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

model::RobotBody read_body(MapReader& body);

/// The `urdf` map of a rig or catalog at `file`; problems are recorded on `top`.
std::optional<UrdfPoses> read_urdf(MapReader& top, const std::string& file);

/// A pose is xyz (+ rpy_deg) in the robot frame, or the pose of a link of the file's URDF.
model::Pose3 read_pose(MapReader& pose, const std::optional<UrdfPoses>& urdf);

}  // namespace rigdesign::io
