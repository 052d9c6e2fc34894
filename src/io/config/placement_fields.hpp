#pragma once
// Fields that rig files and candidate catalogs share: the robot body, the robot description
// (`robot:`, or the older `urdf:` for poses only) and sensor poses (xyz + rpy_deg, or a
// link of the description). Private to io.
#include <map>
#include <optional>
#include <string>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/robot_description.hpp"

namespace rigdesign::io {

model::RobotBody read_body(MapReader& body);

/// What a rig's robot description gives: every link's pose in the robot frame and, for
/// `robot:`, the description itself (with its collision geometry).
struct RobotLinks {
  std::string base_link;     ///< the robot frame's link
  double base_height = 0.0;  ///< [m] the base link's height above the floor (robot frame's z = 0)
  std::string field;         ///< "robot" or "urdf", for messages
  std::map<std::string, model::Pose3> T_base_link;
  std::optional<model::RobotDescription> description;
  /// The description's links and joints where written, and each link's parent (kept when a
  /// legacy `urdf` drops the description itself).
  std::map<std::string, model::SourceLocation> link_where;
  std::map<std::string, model::SourceLocation> joint_where;
  std::map<std::string, std::string> parent_link;
  std::optional<model::RobotSource> source;  ///< how to load the description again
  bool failed = false;  ///< named but not loaded (its errors are already recorded)
};

/// The description's link a pose was taken from, and whether it was taken as an optical frame.
struct MountLink {
  std::string name;
  bool optical = false;
  /// A pose given as numbers may state the sensor's housing link (`housing`); checked by
  /// the loader against the description (model/sensor_housing.hpp).
  std::string housing;
};

/// The `robot` (or `urdf`) map of a rig or catalog at `file`; problems are recorded on `top`.
/// The description is read with `read_description` when given (load_rig_text).
std::optional<RobotLinks> read_robot_links(MapReader& top, const std::string& file,
                                           const DescriptionReader& read_description = {});

/// The keys a rig and a catalog share, read into `robot` in the files' order: `robot` (or
/// `urdf`), `body` (optional with a description: its collision geometry is the body then),
/// `area_height`, `distance_of_interest`. Returns the description's links, for the poses that
/// name them; `body_from_description` tells whether the body came from the description.
struct DescribedRobotFields {
  std::optional<RobotLinks> links;
  bool body_from_description = false;
};
DescribedRobotFields read_described_robot(MapReader& top, const std::string& file,
                                          model::DescribedRobot& robot,
                                          const DescriptionReader& read_description = {});

/// A pose is xyz (+ rpy_deg) in the robot frame, or the pose of a description's link (then
/// named in `used` when given).
model::Pose3 read_pose(MapReader& pose, const std::optional<RobotLinks>& robot,
                       MountLink* used = nullptr);

/// The sensor's housing link for a pose read as `link` (model/sensor_housing.hpp): the stated
/// `housing`, checked against `robot` (an error at `pose` when it is no sensor's own), else
/// derived from the link the pose names. `robot_loaded`: the description loaded (a stated
/// housing is not judged against a failed one).
std::string read_housing(MapReader& pose, const MountLink& link, const model::DescribedRobot& robot,
                         bool robot_loaded);

/// A catalog slot's pose: as read_pose, or with ranges in place of any of xyz's and rpy_deg's
/// six numbers, `{min: 0, max: 40, step: 5}`: every combination of their values, in order
/// (x, y, z, roll, pitch, yaw; the last varying fastest). Errors at the range for min > max,
/// a step <= 0, a step that does not divide max - min, or more than kMaxSlotPoses poses.
/// Or a position swept along a path (issue 55 item 4, read_pose_sweep) with rpy_deg as here.
std::vector<model::SlotPose> read_pose_set(MapReader& pose, const std::optional<RobotLinks>& robot,
                                           const std::vector<model::BodyPart>& parts,
                                           std::vector<model::PoseAxisRange>& ranges);

/// One element of xyz or rpy_deg: a number, or a range {min, max, step} (in the file's unit,
/// m or deg) whose step divides max - min; no values after an error (recorded on `pose`).
struct PoseAxisValues {
  std::vector<double> values;
  bool varies = false;
};
PoseAxisValues read_pose_axis(MapReader& pose, const YAML::Node& element, const std::string& field);

/// A slot pose whose position sweeps a path instead of xyz (issue 55 item 4), each position
/// with every orientation rpy_deg gives (numbers or ranges):
/// - `along: {from: [x, y, z], to: [x, y, z], step: m}`: points of the segment, `step` apart
///   (it must divide the length, so `to` is one of them);
/// - `arc: {centre: [x, y, z], radius: m, from_deg: a, to_deg: b, step_deg: s,
///   face_outward: true}`: points of a horizontal arc about `centre` (azimuths a, a + s, ...,
///   b); facing outward (the default) the yaw is the azimuth plus rpy_deg's yaw;
/// - `on_link: {link: NAME, face: top|bottom|front|back|left|right, edge: FACE, step: m,
///   inset: m}`: points 1 mm proud of a face of the box bounding the link's collision geometry
///   (robot frame: front +x, left +y, top +z), `step` apart on both of the face's axes and `inset`
///   in from its edges; with `edge`, only the face's edge shared with that face.
/// Only rpy_deg's ranges become the slot's ranges (the refinement moves the orientation, not
/// the position along the path). `parts`: the description's collision geometry.
std::vector<model::SlotPose> read_pose_sweep(MapReader& pose,
                                             const std::vector<model::BodyPart>& parts,
                                             std::vector<model::PoseAxisRange>& ranges);

/// Most poses one slot may offer: each costs a raster per angle in memory (about 0.2 MB).
inline constexpr std::size_t kMaxSlotPoses = 400;

}  // namespace rigdesign::io
