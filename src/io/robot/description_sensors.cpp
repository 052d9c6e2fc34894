#include "description_sensors.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <string>

#include "rigdesign/model/rotation.hpp"

namespace rigdesign::io {
namespace {

// The element reached from `node` through `path` (child tags in order), or null.
const xml::Node* child_at(const xml::Node& node, std::initializer_list<const char*> path) {
  const xml::Node* current = &node;
  for (const char* tag : path) {
    const xml::Node* next = nullptr;
    for (const xml::Node& child : current->children) {
      if (child.is_element(tag)) {
        next = &child;
        break;
      }
    }
    if (!next) return nullptr;
    current = next;
  }
  return current;
}

std::string text_in(const xml::Node& element) {
  std::string text;
  for (const xml::Node& child : element.children) {
    if (child.kind == xml::Node::Kind::text) text += child.text;
  }
  return xml::trimmed(text);
}

class SensorReader {
 public:
  SensorReader(const xml::Node& sensor, std::vector<model::Diagnostic>& warnings)
      : sensor_(sensor), warnings_(warnings) {}

  std::string text(std::initializer_list<const char*> path) const {
    const xml::Node* element = child_at(sensor_, path);
    return element ? text_in(*element) : std::string();
  }

  // A finite number at `path`, or nothing (absent, or a warning when it does not read).
  std::optional<double> number(std::initializer_list<const char*> path) const {
    const xml::Node* element = child_at(sensor_, path);
    if (!element) return std::nullopt;
    const std::string written = text_in(*element);
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(written.c_str(), &end);
    if (written.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
      warn(*element, "is '" + written + "'", "a finite number");
      return std::nullopt;
    }
    return value;
  }

  std::optional<int> count(std::initializer_list<const char*> path) const {
    const std::optional<double> value = number(path);
    if (!value) return std::nullopt;
    if (*value < 0 || *value > 1e7 || *value != std::floor(*value)) {
      warn(*child_at(sensor_, path), "is not a whole count", "a whole number of at most 1e7");
      return std::nullopt;
    }
    return static_cast<int>(*value);
  }

  // SDFormat's pose: "x y z roll pitch yaw" (metres, radians).
  model::Pose3 pose() const {
    const xml::Node* element = child_at(sensor_, {"pose"});
    if (!element) return model::Pose3::Identity();
    std::istringstream in(text_in(*element));
    double v[6] = {0, 0, 0, 0, 0, 0};
    for (double& value : v) in >> value;
    std::string rest;
    const bool bad = in.fail() || (in >> rest, !rest.empty()) ||
                     !std::isfinite(v[0] + v[1] + v[2] + v[3] + v[4] + v[5]) ||
                     model::Vec3(v[0], v[1], v[2]).norm() > 1e3;
    if (bad) {
      warn(*element, "is not six finite numbers", "x y z roll pitch yaw (m, rad); taken as 0");
      return model::Pose3::Identity();
    }
    return model::pose_from_xyz_rpy(model::Vec3(v[0], v[1], v[2]), model::Vec3(v[3], v[4], v[5]));
  }

 private:
  void warn(const xml::Node& element, const std::string& problem,
            const std::string& expected) const {
    warnings_.push_back({element.where, "gazebo.sensor." + element.name, problem, expected,
                         model::Severity::warning});
  }
  const xml::Node& sensor_;
  std::vector<model::Diagnostic>& warnings_;
};

model::DescriptionSensor read_sensor(const xml::Node& sensor, const std::string& link,
                                     std::vector<model::Diagnostic>& warnings) {
  const SensorReader read(sensor, warnings);
  model::DescriptionSensor s;
  const std::string* name = sensor.attribute("name");
  const std::string* type = sensor.attribute("type");
  s.name = name ? *name : std::string();
  s.type = type ? *type : std::string();
  s.link = link;
  s.where = sensor.where;
  s.T_link_sensor = read.pose();
  s.topic = read.text({"topic"});
  for (const char* frame : {"gz_frame_id", "ignition_frame_id"}) {
    if (s.frame_id.empty()) s.frame_id = read.text({frame});
  }
  if (s.frame_id.empty()) s.frame_id = read.text({"camera", "optical_frame_id"});
  s.update_rate = read.number({"update_rate"});
  // Gazebo Classic writes a lidar's scan under <ray>, gz sim under <lidar>.
  for (const char* rays : {"ray", "lidar"}) {
    if (!child_at(sensor, {rays})) continue;
    s.horizontal_samples = read.count({rays, "scan", "horizontal", "samples"});
    s.horizontal_min = read.number({rays, "scan", "horizontal", "min_angle"});
    s.horizontal_max = read.number({rays, "scan", "horizontal", "max_angle"});
    s.range_min = read.number({rays, "range", "min"});
    s.range_max = read.number({rays, "range", "max"});
  }
  if (child_at(sensor, {"camera"})) {
    s.horizontal_fov = read.number({"camera", "horizontal_fov"});
    s.width = read.count({"camera", "image", "width"});
    s.height = read.count({"camera", "image", "height"});
    s.range_min = read.number({"camera", "clip", "near"});
    s.range_max = read.number({"camera", "clip", "far"});
  }
  return s;
}

}  // namespace

std::vector<model::DescriptionSensor> description_sensors(
    const xml::Node& robot, std::vector<model::Diagnostic>& warnings) {
  std::vector<model::DescriptionSensor> sensors;
  for (const xml::Node& gazebo : robot.children) {
    if (!gazebo.is_element("gazebo")) continue;
    const std::string* link = gazebo.attribute("reference");
    if (!link) continue;  // a model-wide element holds plugins, not sensors
    for (const xml::Node& sensor : gazebo.children) {
      if (sensor.is_element("sensor")) sensors.push_back(read_sensor(sensor, *link, warnings));
    }
  }
  return sensors;
}

}  // namespace rigdesign::io
