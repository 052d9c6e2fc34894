#pragma once
/// The `sensors:` section of a Clearpath robot.yaml (clearpath_config; docs/clearpath.md cites
/// the schema's sources): lists `lidar2d`, `lidar3d` and `camera` of entries with `model`,
/// `parent`, `xyz` [m], `rpy` [rad] and `ros_parameters`. Read into sensor entries whose models
/// map to sensors.yaml ids, and written back from a rig (issue 34).
#include <string>
#include <vector>

#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::deploy {

/// A Clearpath sensor model and the sensors.yaml id it is, for one device type.
struct ClearpathModel {
  std::string type;        ///< lidar2d, lidar3d or camera
  std::string model;       ///< clearpath_config's model string
  std::string device_key;  ///< the ros_parameters key that picks the device ("" none)
  std::string device;      ///< its value for this entry ("" none); the first row is the default
  std::string sensor_id;   ///< sensors.yaml
};

/// Every mapped model, defaults first within a model.
const std::vector<ClearpathModel>& clearpath_models();

struct ClearpathSensor {
  std::string type;  ///< lidar2d, lidar3d or camera
  int index = 0;     ///< position in its list: Clearpath names it <type>_<index>
  std::string model;
  std::string device;     ///< "" when the entry leaves the default
  std::string sensor_id;  ///< sensors.yaml
  std::string parent;
  model::Vec3 xyz = model::Vec3::Zero();  ///< [m] in the parent link
  model::Vec3 rpy = model::Vec3::Zero();  ///< [rad]
  model::SourceLocation where;            ///< the entry
  model::SourceLocation parent_where;

  std::string name() const { return type + "_" + std::to_string(index); }
};

struct ClearpathRobot {
  std::string file;
  std::string serial_number;  ///< e.g. j100-0000; "" when absent
  std::string ros_namespace;  ///< system.ros2.namespace, else the serial with '-' as '_'
  std::vector<ClearpathSensor> sensors;
  /// Entries rigdesign does not model (IMUs, GPS, colour-only cameras), with why.
  std::vector<std::string> skipped;
};

/// Throws InputError naming file:line:column and the field for a missing file, a section that
/// is not a list of maps, an unknown model (listing the known ones), an xyz or rpy that is not
/// three numbers.
ClearpathRobot read_clearpath_robot(const std::string& path);

/// The rig's mounts as Clearpath entries, in the rig's order within each type: the model of the
/// mount's sensor (the first row naming it; its device where that is not the model's default),
/// the frames' parent and the sensor origin's pose in it. Mounts whose sensor has no Clearpath
/// model are listed in `unmapped`.
std::vector<ClearpathSensor> clearpath_sensors_of(const model::Rig& rig,
                                                  const deploy::SensorFrames& frames,
                                                  std::vector<std::string>& unmapped);

/// A robot.yaml `sensors:` section holding `sensors` (header as comments first).
std::string clearpath_sensors_text(const std::vector<ClearpathSensor>& sensors,
                                   const std::vector<std::string>& unmapped,
                                   const std::string& header);

}  // namespace rigdesign::deploy
