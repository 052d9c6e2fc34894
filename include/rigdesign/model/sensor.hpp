#pragma once
/// The sensor datasheet model: a sensor with its price and the modes it can run in
/// (DESIGN.md section 3). All values SI: metres, seconds, radians, bytes, USD.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/fov_shape.hpp"
#include "rigdesign/model/housing_solid.hpp"
#include "rigdesign/model/name_table.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

enum class Technology {
  tof,
  structured_light,
  active_stereo,
  passive_stereo,
  lidar_3d_spinning,
  lidar_2d,
  solid_state_lidar,
};
inline constexpr NameTable<Technology, 7> kTechnologyNames = {{
    {Technology::tof, "tof"},
    {Technology::structured_light, "structured_light"},
    {Technology::active_stereo, "active_stereo"},
    {Technology::passive_stereo, "passive_stereo"},
    {Technology::lidar_3d_spinning, "lidar_3d_spinning"},
    {Technology::lidar_2d, "lidar_2d"},
    {Technology::solid_state_lidar, "solid_state_lidar"},
}};
static_assert(covers_in_order(kTechnologyNames) &&
              kTechnologyNames.size() ==
                  static_cast<std::size_t>(Technology::solid_state_lidar) + 1);

/// Lighting conditions of requirement R8, in a fixed order for tables.
enum class LightCondition { dark, indoor, sunlight };
inline constexpr NameTable<LightCondition, 3> kLightConditionNames = {{
    {LightCondition::dark, "dark"},
    {LightCondition::indoor, "indoor"},
    {LightCondition::sunlight, "sunlight"},
}};
static_assert(covers_in_order(kLightConditionNames) &&
              kLightConditionNames.size() ==
                  static_cast<std::size_t>(LightCondition::sunlight) + 1);
inline constexpr std::array<LightCondition, 3> kLightConditions = {
    LightCondition::dark, LightCondition::indoor, LightCondition::sunlight};

/// Whether a sensor works under each lighting condition (true = immune to it).
struct LightImmunity {
  bool dark = false;
  bool indoor = false;
  bool sunlight = false;
  bool immune_to(LightCondition condition) const;
};

/// Range noise (one standard deviation) as a function of distance d [m]:
/// sigma(d) = a + b*d + c*d^2, from the datasheet (DESIGN.md section 3).
struct NoiseModel {
  double a = 0.0;  ///< [m]
  double b = 0.0;  ///< [-]
  double c = 0.0;  ///< [1/m]
  double sigma(double distance) const;
};

/// How a number was obtained, so estimates are never mistaken for datasheet values.
enum class Basis { datasheet, measured, estimate };
inline constexpr NameTable<Basis, 3> kBasisNames = {{
    {Basis::datasheet, "datasheet"},
    {Basis::measured, "measured"},
    {Basis::estimate, "estimate"},
}};
static_assert(covers_in_order(kBasisNames) &&
              kBasisNames.size() == static_cast<std::size_t>(Basis::estimate) + 1);

/// Driver CPU load U_p of one running sensor (paper 1, eq. 5), in core-equivalents of the
/// reference machine named in sensors.yaml: a fixed part plus a cost per delivered point,
/// so one entry in `mode_defaults` serves every mode of a sensor.
struct DriverCpuLoad {
  double cores = 0.0;              ///< fixed part [core-equivalents]
  double seconds_per_point = 0.0;  ///< [core-seconds per point]
  Basis basis = Basis::estimate;
  std::string note;
  double load(double points_per_second) const {
    return cores + seconds_per_point * points_per_second;
  }
};

/// What a sensor's vendor says about several units lighting each other (sensors.yaml
/// `emitter.interferes`): they corrupt each other's depth, they do not (Intel's D4xx), or
/// nothing was found.
enum class Crosstalk { unknown, interferes, immune };

/// The light an active sensor sends out (issue 38, item 2) and what its vendor supports
/// against crosstalk between units, with the source of each fact.
struct Emitter {
  std::optional<double> wavelength;  ///< [m]; nothing: not published
  std::string modulation;            ///< "AMCW ToF", "static dot pattern", "pulsed ToF"
  Crosstalk crosstalk = Crosstalk::unknown;
  /// Mitigations the vendor supports: sync (a hardware sync cable or trigger), delay (captures
  /// offset in time), phase_lock (spinning lidars locked to a common phase), channels
  /// (modulation channels), emitter_off.
  std::vector<std::string> mitigation;
  std::optional<double> min_delay;  ///< [s] offset synchronised units need; nothing: none
  std::string source;
  SourceLocation where;

  bool supports(const std::string& measure) const;
};

/// How a structured-light or stereo camera finds depth (issue 54 item 1): by matching a window
/// of pixels against a pattern or the other image; a surface that fills less than about half
/// of the window along a row or a column takes the depth of what fills the rest, or none.
struct DepthMatching {
  int window_px = 0;          ///< the matching window's side in pixels
  double window_angle = 0.0;  ///< [rad] that side as an angle: window_px x FOV / image width
  /// [m px] baseline times focal length: depths z1, z2 are one surface to the matcher while
  /// their disparities differ by less than a pixel, |z1 - z2| < z^2 / baseline_focal.
  double baseline_focal = 0.0;
  std::string source;
  SourceLocation where;
};

struct SensorMode {
  std::string id;
  FieldOfView fov;
  double min_range = 0.0;  ///< [m] from the sensor origin
  double max_range = 0.0;  ///< [m]
  double frequency = 0.0;  ///< [Hz] full frames (or revolutions) per second
  /// [rad] angle between neighbouring rays; vertical is empty for single-row scanners.
  double angular_resolution_h = 0.0;
  std::optional<double> angular_resolution_v;
  double points_per_frame = 0.0;
  double bytes_per_frame = 0.0;  ///< [B] data on the wire per frame
  NoiseModel noise;
  LightImmunity light;
  DriverCpuLoad driver_cpu;
  /// The light it sends out; nothing for a passive sensor (or one whose file says nothing).
  std::optional<Emitter> emitter;
  /// [rad] How much narrower than nominal a unit's full horizontal and vertical angles may be
  /// (a datasheet's "87 +- 3 deg"): the mounting tolerance judges the narrowest (issue 38).
  std::optional<std::array<double, 2>> fov_spread;
  /// Depth by window matching (structured light, stereo); nothing: each ray its own return.
  std::optional<DepthMatching> depth_matching;
  SourceLocation where;

  /// The coarser of the two ray spacings [rad]: what sets the smallest obstacle seen.
  double worst_angular_resolution() const;
  /// A camera mode (FovShape::is_camera of its FOV shape).
  bool is_camera() const { return fov.shape().is_camera(); }
  /// This mode with its FOV at the datasheet's narrowest (fov_spread off each full angle of a
  /// pyramid, the horizontal one off a cone's apex); itself without a spread.
  SensorMode narrowest() const;
};

struct Price {
  double usd = 0.0;
  int year = 0;
  Basis basis = Basis::datasheet;
  std::string source;
};

/// The sensor's ROS 2 driver as its package's default launch file runs it (sensors.yaml
/// `ros2`; the research with repository, commit, file and line is data/ros_drivers/).
struct RosDriver {
  bool exists = false;  ///< false: no maintained ROS 2 driver for Humble or Jazzy
  std::string package;
  std::string launch;                ///< the command that starts it, arguments included
  std::vector<std::string> distros;  ///< of humble and jazzy, those it is released or built for
  std::string topic;                 ///< the range data's topic, as the default launch resolves it
  std::string message_type;          ///< sensor_msgs/msg/PointCloud2 or sensor_msgs/msg/LaserScan
  std::string frame_id;              ///< the frame the data is stamped with
  /// Frames the driver (or its launch file) broadcasts itself, the root first: a robot's URDF
  /// gives the root and must not give the others. Empty: the URDF gives frame_id.
  std::vector<std::string> driver_frames;
  /// Issue 52 item 4: the pose of frame_id in the root of driver_frames that the driver's own
  /// static transforms give (data/ros_drivers/driver_transforms.yaml), and whether frame_id is
  /// an optical frame (z forward); the export places the root so that the data frame lands on
  /// the designed pose. Nothing: not recorded (the root is placed at the sensor origin).
  std::optional<Pose3> T_root_data;
  bool data_frame_optical = false;
  std::string frame_parameter;  ///< how to make it stamp another frame
  std::string note;             ///< what a deployment must know (arguments to add, clashes)
  std::string source;           ///< where the facts are recorded
  SourceLocation where;
};

struct Sensor {
  std::string id;
  std::string name;
  Technology technology = Technology::tof;
  std::string source;  ///< datasheet document or URL the values come from
  Price price;
  std::vector<SensorMode> modes;
  std::optional<RosDriver> ros2;  ///< nothing: not researched
  /// The datasheet housing; nothing: a point (a user's library may leave it out, every
  /// bundled sensor has one).
  std::optional<HousingSolid> housing;
  SourceLocation where;

  const SensorMode* find_mode(const std::string& mode_id) const;
};

/// The contents of a sensors.yaml file.
struct SensorLibrary {
  std::string reference_machine;  ///< what one "core-equivalent" of driver load means
  std::vector<Sensor> sensors;
  std::string file;

  const Sensor* find(const std::string& sensor_id) const;
  /// The mode a mount's references name; std::logic_error when they do not resolve (callers
  /// have checked the references first, io::check_rig_references).
  const SensorMode& resolved_mode(const std::string& sensor_id, const std::string& mode_id) const;
};

std::string to_string(Technology technology);
std::string to_string(LightCondition condition);
std::string to_string(Basis basis);

}  // namespace rigdesign::model
