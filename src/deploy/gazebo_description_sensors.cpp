#include "rigdesign/deploy/gazebo_description_sensors.hpp"

#include <cmath>
#include <set>

#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {
namespace {

// A sensor this far outside a housing is still in it: the most sensors.yaml lets a data
// origin lie outside its housing (the sensor library loader's check).
constexpr double kHousingMargin = 0.01;  // [m]
// Without a housing, a description sensor this close to the data origin is the mount's.
constexpr double kSameSensorDistance = 0.05;  // [m]

// The types gz sim's Sensors system renders (gz-sim src/SdfEntityCreator.cc and
// src/rendering/RenderUtil.cc at 93bbf3e): SDFormat reads gpu_ray as gpu_lidar. A CPU `ray` or
// `lidar` has a system only since gz-sim 839e621 (2026-05-20), after Harmonic.
const std::set<std::string> kRendered = {"gpu_lidar",   "gpu_ray", "depth_camera", "depth",
                                         "rgbd_camera", "rgbd",    "camera"};

std::string number(double value) {
  return model::format_number(value, 4);
}

std::string degrees(double radians) {
  return number(model::rad_to_deg(radians));
}

bool differs(double a, double b, double tolerance) {
  return std::abs(a - b) > tolerance;
}

void compare_lidar(const model::DescriptionSensor& own, const GazeboSensor& designed,
                   std::vector<std::string>& notes) {
  if (own.horizontal_samples && *own.horizontal_samples != designed.horizontal_samples) {
    notes.push_back(std::to_string(*own.horizontal_samples) + " rays a turn of its scan (design " +
                    std::to_string(designed.horizontal_samples) + ")");
  }
  if (own.horizontal_min && own.horizontal_max &&
      (differs(*own.horizontal_min, designed.horizontal_min, 1e-3) ||
       differs(*own.horizontal_max, designed.horizontal_max, 1e-3))) {
    notes.push_back("scans " + degrees(*own.horizontal_min) + ".." + degrees(*own.horizontal_max) +
                    " deg (design " + degrees(designed.horizontal_min) + ".." +
                    degrees(designed.horizontal_max) + ")");
  }
}

void compare_camera(const model::DescriptionSensor& own, const GazeboSensor& designed,
                    std::vector<std::string>& notes) {
  if (own.horizontal_fov && differs(*own.horizontal_fov, designed.horizontal_fov, 1e-3)) {
    notes.push_back("horizontal FOV " + degrees(*own.horizontal_fov) + " deg (design " +
                    degrees(designed.horizontal_fov) + ")");
  }
  if (own.width && own.height && (*own.width != designed.width || *own.height != designed.height)) {
    notes.push_back("image " + std::to_string(*own.width) + "x" + std::to_string(*own.height) +
                    " (design " + std::to_string(designed.width) + "x" +
                    std::to_string(designed.height) + ")");
  }
}

}  // namespace

std::string gz_scoped_topic(const std::string& sensor_name) {
  return "/world/<world>/model/<model>/link/<link>/sensor/" + sensor_name + "/...";
}

std::optional<model::DescriptionSensor> description_sensor_of(const model::Rig& rig,
                                                              const model::Mount& mount,
                                                              const model::SensorLibrary& library) {
  const model::Sensor* sensor = library.find(mount.sensor_id);
  for (const model::DescriptionSensor& own : rig.description_sensors) {
    const auto link = rig.link_poses.find(own.link);
    if (link == rig.link_poses.end()) continue;
    const model::Vec3 origin = (link->second * own.T_link_sensor).translation();
    const bool inside =
        sensor && sensor->housing
            ? geometry::contains(
                  geometry::housing_solid(*sensor->housing, mount.T_robot_sensor, -kHousingMargin),
                  origin)
            : (origin - mount.T_robot_sensor.translation()).norm() <= kSameSensorDistance;
    if (inside) return own;
  }
  return std::nullopt;
}

std::vector<std::string> description_sensor_differences(const model::DescriptionSensor& own,
                                                        const GazeboSensor& designed) {
  std::vector<std::string> notes;
  if (!kRendered.count(own.type)) {
    notes.push_back("its type '" + own.type +
                    "' is Gazebo Classic's CPU sensor, which gz sim (Harmonic) does not render");
  }
  const bool lidar_type =
      own.type.find("ray") != std::string::npos || own.type.find("lidar") != std::string::npos;
  if (lidar_type != (designed.type == GazeboSensorType::gpu_lidar)) {
    notes.push_back("it is a " + own.type + ", the design a " + to_string(designed.type));
  }
  if (own.update_rate &&
      differs(*own.update_rate, designed.update_rate, 1e-3 * designed.update_rate)) {
    notes.push_back(number(*own.update_rate) + " Hz (design " + number(designed.update_rate) + ")");
  }
  if (lidar_type) {
    compare_lidar(own, designed, notes);
  } else {
    compare_camera(own, designed, notes);
  }
  if ((own.range_min && differs(*own.range_min, designed.range_min, 1e-3)) ||
      (own.range_max && differs(*own.range_max, designed.range_max, 1e-3))) {
    notes.push_back("ranges " + (own.range_min ? number(*own.range_min) : std::string("?")) + ".." +
                    (own.range_max ? number(*own.range_max) : std::string("?")) + " m (design " +
                    number(designed.range_min) + ".." + number(designed.range_max) + ")");
  }
  if (own.topic.empty()) {
    notes.push_back("it sets no <topic>: gz sim publishes it under " + gz_scoped_topic(own.name) +
                    ", which bridge.yaml cannot name");
  }
  if (own.frame_id != designed.frame_id) {
    notes.push_back(
        own.frame_id.empty()
            ? "it stamps gz's scoped name, not the frame nav2 reads (" + designed.frame_id + ")"
            : "it stamps frame '" + own.frame_id + "', nav2 reads '" + designed.frame_id + "'");
  }
  return notes;
}

}  // namespace rigdesign::deploy
