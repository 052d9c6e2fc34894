#include "rigdesign/deploy/clearpath/clearpath_sensors.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/io/emit/yaml_emit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/rotation.hpp"

namespace rigdesign::deploy {
namespace {

const std::vector<std::string> kRangeSensorTypes = {"lidar2d", "lidar3d", "camera"};
// Clearpath models rigdesign knows but does not model: no range data.
const std::vector<std::string> kColourOnly = {"flir_blackfly", "axis_camera"};

// `node_key.param` inside ros_parameters, nested (`{node: {general: {camera_model: x}}}`) or
// flattened as clearpath_config writes it back (`{node: {general.camera_model: x}}`).
std::string device_value(const YAML::Node& parameters, const std::string& key) {
  // A missing key gives an invalid node, whose type yaml-cpp throws for: IsDefined() first.
  if (key.empty() || !parameters.IsDefined() || !parameters.IsMap()) return "";
  const std::size_t dot = key.find('.');
  const std::string node = key.substr(0, dot), rest = key.substr(dot + 1);
  const YAML::Node of_node = parameters[node];
  if (!of_node.IsDefined() || !of_node.IsMap()) return "";
  const YAML::Node flat = of_node[rest];
  if (flat.IsDefined() && flat.IsScalar()) return flat.Scalar();
  YAML::Node current;
  current.reset(of_node);
  std::istringstream parts(rest);
  for (std::string part; std::getline(parts, part, '.');) {
    if (!current.IsMap()) return "";
    // Through a const node: yaml-cpp's non-const operator[] adds the key to the document.
    const YAML::Node& read_only = current;
    const YAML::Node next = read_only[part];
    if (!next.IsDefined()) return "";
    current.reset(next);
  }
  return current.IsDefined() && current.IsScalar() ? current.Scalar() : "";
}

std::string known_models(const std::string& type) {
  std::vector<std::string> names;
  for (const ClearpathModel& m : clearpath_models()) {
    if (m.type == type && std::find(names.begin(), names.end(), m.model) == names.end())
      names.push_back(m.model);
  }
  return model::join(names);
}

model::Vec3 triple(io::MapReader& entry, const std::string& key, const std::string& unit) {
  const std::optional<std::vector<double>> values = entry.numbers(
      key, io::Need::optional, 3, 3, "three numbers [" + unit + "], e.g. [0.0, 0.0, 0.0]");
  return values ? model::Vec3((*values)[0], (*values)[1], (*values)[2]) : model::Vec3::Zero();
}

}  // namespace

const std::vector<ClearpathModel>& clearpath_models() {
  // clearpath_config 0.3.4 (sensors/types/*.py; docs/clearpath.md has file and line); the
  // Ouster from the 2.x (Jazzy) documentation.
  static const std::vector<ClearpathModel> models = {
      {"lidar2d", "hokuyo_ust", "", "", "hokuyo_ust_10lx"},
      {"lidar2d", "sick_lms1xx", "", "", "sick_lms100"},
      {"lidar3d", "velodyne_lidar", "velodyne_driver_node.model", "VLP16", "velodyne_vlp16"},
      {"lidar3d", "velodyne_lidar", "velodyne_driver_node.model", "32C", "velodyne_vlp32c"},
      {"lidar3d", "ouster_os1", "", "", "ouster_os1_64"},
      {"camera", "intel_realsense", "intel_realsense.device_type", "d435", "realsense_d435"},
      {"camera", "intel_realsense", "intel_realsense.device_type", "d415", "realsense_d415"},
      {"camera", "stereolabs_zed", "stereolabs_zed.general.camera_model", "zed2", "zed2"},
      {"camera", "stereolabs_zed", "stereolabs_zed.general.camera_model", "zedx", "zed_x"},
      {"camera", "luxonis_oakd", "", "", "oakd_pro"},
  };
  return models;
}

ClearpathRobot read_clearpath_robot(const std::string& path) {
  model::Diagnostics diagnostics;
  io::MapReader top = io::read_document_map(
      path, diagnostics, "a Clearpath robot.yaml: serial_number, version, sensors, ...");
  ClearpathRobot robot;
  robot.file = path;
  robot.serial_number = top.text("serial_number", io::Need::optional).value_or("");
  robot.ros_namespace = robot.serial_number;
  std::replace(robot.ros_namespace.begin(), robot.ros_namespace.end(), '-', '_');
  if (auto system = top.map("system", io::Need::optional)) {
    if (auto ros2 = system->map("ros2", io::Need::optional)) {
      if (auto ns = ros2->text("namespace", io::Need::optional)) robot.ros_namespace = *ns;
    }
  }
  if (auto sensors =
          top.map("sensors", io::Need::optional, "lists lidar2d, lidar3d, camera, ...")) {
    for (const std::string& type : kRangeSensorTypes) {
      std::vector<io::MapReader> entries =
          sensors->maps(type, io::Need::optional, "a list of sensor entries (maps with a model)");
      for (std::size_t i = 0; i < entries.size(); ++i) {
        io::MapReader& entry = entries[i];
        ClearpathSensor sensor;
        sensor.type = type;
        sensor.index = static_cast<int>(i);
        sensor.where = entry.location();
        sensor.model = entry.text("model", io::Need::required, "a Clearpath model").value_or("");
        sensor.parent = entry.text("parent", io::Need::optional).value_or("default_mount");
        sensor.parent_where = entry.location("parent");
        sensor.xyz = triple(entry, "xyz", "m");
        sensor.rpy = triple(entry, "rpy", "rad");
        const YAML::Node parameters = entry.node("ros_parameters");
        entry.boolean("urdf_enabled", io::Need::optional);
        entry.boolean("launch_enabled", io::Need::optional);
        entry.node("republishers");
        entry.reject_unknown_keys();
        if (std::find(kColourOnly.begin(), kColourOnly.end(), sensor.model) != kColourOnly.end()) {
          robot.skipped.push_back(sensor.name() + " (" + sensor.model +
                                  "): a colour camera, no range data");
          continue;
        }
        // The model's rows share one device key; no device named: the first row, the default.
        std::vector<const ClearpathModel*> rows;
        for (const ClearpathModel& m : clearpath_models())
          if (m.type == type && m.model == sensor.model) rows.push_back(&m);
        if (rows.empty()) {
          if (!sensor.model.empty())
            entry.require(false, "model",
                          "'" + sensor.model + "' has no sensor in rigdesign's library",
                          "one of " + known_models(type));
          continue;
        }
        sensor.device = device_value(parameters, rows.front()->device_key);
        const ClearpathModel* match = rows.front();
        if (!sensor.device.empty()) {
          match = nullptr;
          for (const ClearpathModel* row : rows)
            if (row->device == sensor.device) match = row;
        }
        if (!match) {
          std::string devices;
          for (const ClearpathModel* row : rows)
            devices += (devices.empty() ? "" : ", ") + row->device;
          entry.require(false, "ros_parameters",
                        rows.front()->device_key + " '" + sensor.device +
                            "' has no sensor in "
                            "rigdesign's library",
                        "one of " + devices);
          continue;
        }
        sensor.sensor_id = match->sensor_id;
        robot.sensors.push_back(sensor);
      }
    }
    // IMUs, GPS and whatever kinds clearpath_config adds later (2.x documents ins and ptu):
    // not range sensors, so not refused either.
    for (const char* other : {"imu", "gps"}) {
      for (const io::MapReader& entry :
           sensors->maps(other, io::Need::optional, "a list of entries")) {
        (void)entry;
        robot.skipped.push_back(std::string(other) + ": not a range sensor");
      }
    }
  }
  diagnostics.throw_if_errors();
  return robot;
}

std::vector<ClearpathSensor> clearpath_sensors_of(const model::Rig& rig,
                                                  const deploy::SensorFrames& frames,
                                                  std::vector<std::string>& unmapped) {
  std::vector<ClearpathSensor> sensors;
  std::map<std::string, int> count_of_type;
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    const std::vector<ClearpathModel>& models = clearpath_models();
    const auto row = std::find_if(models.begin(), models.end(), [&](const ClearpathModel& c) {
      return c.sensor_id == mount.sensor_id;
    });
    if (row == models.end()) {
      unmapped.push_back(mount.id + " (" + mount.sensor_id + ")");
      continue;
    }
    const auto first_of_model =
        std::find_if(models.begin(), models.end(),
                     [&](const ClearpathModel& c) { return c.model == row->model; });
    ClearpathSensor sensor;
    sensor.type = row->type;
    sensor.index = count_of_type[row->type]++;
    sensor.model = row->model;
    sensor.device = row == first_of_model ? "" : row->device;
    sensor.sensor_id = mount.sensor_id;
    sensor.parent = frames.parent;
    const model::Pose3& T = frames.frames[m].T_parent_link;
    sensor.xyz = T.translation();
    sensor.rpy = model::rpy_from_rotation(T.linear());
    sensors.push_back(sensor);
  }
  return sensors;
}

std::string clearpath_sensors_text(const std::vector<ClearpathSensor>& sensors,
                                   const std::vector<std::string>& unmapped,
                                   const std::string& header) {
  std::ostringstream out;
  out << io::yaml_comment(header);
  out << io::yaml_comment(
      "The `sensors:` section of a Clearpath robot.yaml (clearpath_config): merge it into "
      "/etc/clearpath/robot.yaml. xyz [m] and rpy [rad] place each sensor's origin in its "
      "parent link; Clearpath names them <type>_<index> in list order.");
  if (!unmapped.empty()) {
    std::string ids;
    for (const std::string& id : unmapped) ids += (ids.empty() ? "" : ", ") + id;
    out << io::yaml_comment("No Clearpath model for: " + ids);
  }
  const auto floats = [](const model::Vec3& v) {
    // clearpath_config asserts floats: a whole number is written with its point.
    const auto one = [](double x) {
      std::string text = model::exact_number(std::abs(x) < 1e-15 ? 0.0 : x);
      if (text.find_first_of(".eE") == std::string::npos) text += ".0";
      return text;
    };
    return "[" + one(v.x()) + ", " + one(v.y()) + ", " + one(v.z()) + "]";
  };
  out << "sensors:\n";
  for (const std::string& type : kRangeSensorTypes) {
    bool any = false;
    for (const ClearpathSensor& s : sensors) {
      if (s.type != type) continue;
      if (!any) out << "  " << type << ":\n";
      any = true;
      out << "    - model: " << s.model << "\n"
          << "      urdf_enabled: true\n"
          << "      launch_enabled: true\n"
          << "      parent: " << io::yaml_scalar(s.parent) << "\n"
          << "      xyz: " << floats(s.xyz) << "\n"
          << "      rpy: " << floats(s.rpy) << "\n";
      for (const ClearpathModel& m : clearpath_models()) {
        if (m.model != s.model || m.device_key.empty() || m.device != s.device) continue;
        const std::size_t dot = m.device_key.find('.');
        out << "      ros_parameters:\n        " << m.device_key.substr(0, dot) << ":\n          "
            << m.device_key.substr(dot + 1) << ": " << io::yaml_scalar(s.device) << "\n";
        break;
      }
    }
    if (!any) out << "  " << type << ": []\n";
  }
  return out.str();
}

}  // namespace rigdesign::deploy
