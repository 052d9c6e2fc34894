#pragma once
/// A rig: the robot body, the distance of interest and the mounted sensors (DESIGN.md
/// section 3). Frames follow REP-103: the robot frame is on the floor under the robot's
/// centre, x forward, y left, z up.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/description_sensor.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/housing_solid.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/mount_limits.hpp"
#include "rigdesign/model/source_location.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::model {

/// A vertical cylinder of a robot's collision geometry (a standoff, a round base), kept
/// round so that its shadow is exact.
struct VerticalCylinder {
  Vec2 centre = Vec2::Zero();  ///< [m] axis position in the robot frame
  double radius = 0.0;         ///< [m]
  double z_min = 0.0;          ///< [m]
  double z_max = 0.0;          ///< [m]
};

/// One <collision> element of a robot description, in the robot frame: a vertical cylinder,
/// or triangles (boxes and meshes exactly; tilted cylinders and spheres tessellated).
struct BodyPart {
  std::string link;
  std::optional<VerticalCylinder> cylinder;
  TriangleMesh triangles;
  double tessellation_error = 0.0;  ///< [m] largest distance of the triangles from the true surface
  SourceLocation where;
};

/// How far a mount may sit from its nominal pose (issue 38: brackets bend, cameras sit a degree
/// off): half-widths of a box of errors. A pose in the box is the nominal one rotated about the
/// sensor's own x, y, z axes by (roll, pitch, yaw) and moved in the robot frame by xyz.
struct PoseTolerance {
  Vec3 xyz = Vec3::Zero();  ///< [m] half-widths along the robot frame's x, y, z
  Vec3 rpy = Vec3::Zero();  ///< [rad] half-widths about the sensor's x (roll), y (pitch), z (yaw)
  SourceLocation where;

  bool any() const { return xyz.any() || rpy.any(); }
};

/// The robot's body, which bounds the area to perceive (rho >= r(theta), z in [0, h]) and
/// occludes: a solid cylinder or footprint prism from the floor to `height`, or the union of
/// a robot description's collision geometry (`parts`).
struct RobotBody {
  double height = 0.0;  ///< h [m]: the top of the body (of the collision geometry's parts)
  /// Cylinder radius r [m]; with a footprint or parts, the largest horizontal distance of
  /// the body from the robot's vertical axis.
  double radius = 0.0;
  std::vector<Vec2> footprint;  ///< optional prism cross-section, counter-clockwise [m]
  std::vector<BodyPart> parts;  ///< a description's collision geometry; empty otherwise
  /// Top of the area to perceive [m]; nothing means the body's height.
  std::optional<double> area_height;
  /// The rig's `body` entry (or `robot`, for a description's geometry): where a verdict the
  /// body decides points; each part keeps its own line in the description.
  SourceLocation where;

  bool has_parts() const { return !parts.empty(); }
  double area_top() const { return area_height.value_or(height); }
};

/// What a rig does against crosstalk between this mount's emitter and others' (issue 38, item
/// 2; sensors.yaml `emitter.mitigation` says what each sensor supports): mounts in the same
/// `sync` group are wired to one hardware sync and capture at their `delay` offsets; mounts on
/// different modulation `channel`s do not demodulate each other's light.
struct CrosstalkMitigation {
  std::string sync_group;       ///< empty: not synchronised
  std::optional<double> delay;  ///< [s] capture offset within the group
  std::optional<int> channel;
  SourceLocation where;
};

struct Mount {
  std::string id;
  std::string sensor_id;
  std::string mode_id;
  /// Maps sensor-frame points into the robot frame (sensor frame: x along the optical axis).
  Pose3 T_robot_sensor = Pose3::Identity();
  std::optional<double> distance_of_interest;  ///< [m] overrides the rig's for this mount
  /// [Hz] The stack passes on at most this many of the sensor's frames a second (paper 2
  /// throttled its lidar to 5 Hz and its Kinect to 2 Hz to save CPU): the rate F the rig is
  /// judged on and the scenarios sense at. Nothing: every frame of the mode.
  std::optional<double> throttle_hz;
  SourceLocation throttle_where;
  SourceLocation where;         ///< the mount's entry
  SourceLocation sensor_where;  ///< its `sensor` value, for findings about the reference
  SourceLocation mode_where;    ///< its `mode` value
  SourceLocation pose_where;    ///< its `pose`
  /// The description's link the pose was taken from (`pose: {urdf_link: ...}`), empty for a
  /// pose given by numbers: the export reuses that link instead of adding one.
  std::string urdf_link;
  /// The link is a camera's optical frame (z forward): the frame the driver stamps with.
  bool urdf_link_optical = false;
  /// The description link whose collision geometry is this sensor's own housing, the only
  /// one it sees through (model/sensor_housing.hpp); empty: none, every part is solid to it.
  std::string housing_link;
  /// `recessed: true` (issue 52): the body's shell has a pocket for this sensor (a window cut
  /// in its cover), so its datasheet housing may sit inside the cylinder or prism or the
  /// description's parts; check's B2 still holds it to every other housing, and B1 its data
  /// origin to the outside of the body.
  bool recessed = false;
  /// `ros: {namespace, topic, frame}`: how this mount's driver is run, where it differs from
  /// the driver's defaults (sensors.yaml `ros2`); empty: the default.
  std::string ros_namespace;  ///< the namespace the driver is launched in
  std::string ros_topic;      ///< the data's topic, absolute
  std::string ros_frame;      ///< the frame the driver is set to stamp the data with
  /// What the deployed stack removes from this mount's data (`check` with nav2 parameters and
  /// self-filters); empty for the design itself.
  MountLimits limits;
  /// This mount's own mounting tolerance; nothing: the rig's.
  std::optional<PoseTolerance> tolerance;
  /// `crosstalk: {sync, delay_us, channel}`; nothing: no measure stated.
  std::optional<CrosstalkMitigation> crosstalk;
};

/// How a rig (or catalog) names its robot description, resolved: enough to load the same
/// robot again (`check` and `export` of a chosen rig, a round trip with the exported macro).
struct RobotSource {
  std::string description;  ///< the .urdf or .urdf.xacro, absolute or relative to the cwd
  std::map<std::string, std::string> args;
  std::map<std::string, std::string> environment;
  std::vector<std::string> package_paths;  ///< as resolved (absolute or relative to the cwd)
  std::string base_link;                   ///< as given; empty: the loader's choice
  double base_link_height = 0.0;           ///< [m]
  std::string expander = "auto";           ///< auto, builtin or xacro
  bool poses_only = false;                 ///< a legacy `urdf:` entry (no collision geometry)
};

/// The robot a rig or a candidate catalog stands on, as the keys both files share describe it
/// (`robot` or `urdf`, `body`, `area_height`, `distance_of_interest`), read by one loader
/// function and copied whole into the rig `select` chooses.
struct DescribedRobot {
  /// The body: the robot description's collision geometry (`robot:`), or `body:`; its
  /// area_height from the file or the requirements.
  RobotBody body;
  double distance_of_interest = 0.0;  ///< d [m]
  /// With a robot description: the link the robot frame stands on (REP-105's base_footprint,
  /// or the description's base link), its height above the floor, and every link's pose in
  /// the robot frame, so that exported sensor frames can hang from any link. Without one the
  /// robot frame is base_footprint and `link_poses` is empty.
  std::string base_link = "base_footprint";
  double base_link_height = 0.0;  ///< [m]
  std::map<std::string, Pose3> link_poses;
  /// The description's links and joints where they are written, and each link's parent: what
  /// the exported sensor macro must not name again, and where a link's children are.
  std::map<std::string, SourceLocation> link_where;
  std::map<std::string, SourceLocation> joint_where;
  std::map<std::string, std::string> parent_link;
  /// The sensors the description declares for Gazebo (their links are in link_poses).
  std::vector<DescriptionSensor> description_sensors;
  /// The description the links come from; nothing without one.
  std::optional<RobotSource> robot;
};

/// A mast, bracket or plate the rig declares (issue 52 item 3): a simple solid in the robot
/// frame that holds sensors. It is solid for every sensor, as the body is, and no housing may
/// cut into it.
struct RigSupport {
  std::string id;
  HousingSolid solid;  ///< its shape and size, centred on its pose
  Pose3 T_robot_support = Pose3::Identity();
  double price = 0.0;  ///< [USD] `price_usd`, counted with the sensors' cost C_s; 0: not given
  SourceLocation where;
};

struct Rig : DescribedRobot {
  std::string name;
  std::vector<Mount> mounts;
  std::vector<RigSupport> supports;
  std::string sensor_library;  ///< path as written in the file (relative to it), may be empty
  std::string requirements;    ///< path as written in the file (relative to it), may be empty
  SourceLocation sensor_library_where;
  SourceLocation requirements_where;
  std::string file;
  SourceLocation where;
  /// What the loader noticed that is not an error (e.g. a link used in the other frame
  /// convention than its axes suggest).
  std::vector<Diagnostic> load_warnings;
  /// Every mount's mounting tolerance unless the mount gives its own; nothing: none.
  std::optional<PoseTolerance> tolerance;

  /// The tolerance `mount` is judged with: its own, else the rig's, else nothing.
  const PoseTolerance* tolerance_for(const Mount& mount) const {
    if (mount.tolerance) return &*mount.tolerance;
    return tolerance ? &*tolerance : nullptr;
  }

  /// The distance at which a mount's resolution and noise are judged [m].
  double distance_for(const Mount& mount) const {
    return mount.distance_of_interest.value_or(distance_of_interest);
  }
  /// The mount called `id` (deployed files name sources and filters after mounts), or null.
  const Mount* find_mount(const std::string& id) const {
    for (const Mount& mount : mounts) {
      if (mount.id == id) return &mount;
    }
    return nullptr;
  }
  /// Every mount's id, in the rig's order (for "expected one of" messages).
  std::vector<std::string> mount_ids() const {
    std::vector<std::string> ids;
    for (const Mount& mount : mounts) ids.push_back(mount.id);
    return ids;
  }
};

}  // namespace rigdesign::model
