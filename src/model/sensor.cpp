#include "rigdesign/model/sensor.hpp"

#include <algorithm>

namespace rigdesign::model {

bool LightImmunity::immune_to(LightCondition condition) const {
  switch (condition) {
    case LightCondition::dark: return dark;
    case LightCondition::indoor: return indoor;
    case LightCondition::sunlight: return sunlight;
  }
  return false;
}

double NoiseModel::sigma(double distance) const {
  return a + b * distance + c * distance * distance;
}

double SensorMode::worst_angular_resolution() const {
  return std::max(angular_resolution_h, angular_resolution_v.value_or(0.0));
}

const SensorMode* Sensor::find_mode(const std::string& mode_id) const {
  const auto it = std::find_if(modes.begin(), modes.end(),
                               [&](const SensorMode& mode) { return mode.id == mode_id; });
  return it == modes.end() ? nullptr : &*it;
}

const Sensor* SensorLibrary::find(const std::string& sensor_id) const {
  const auto it = std::find_if(sensors.begin(), sensors.end(),
                               [&](const Sensor& sensor) { return sensor.id == sensor_id; });
  return it == sensors.end() ? nullptr : &*it;
}

std::string to_string(Technology technology) {
  switch (technology) {
    case Technology::tof: return "tof";
    case Technology::structured_light: return "structured_light";
    case Technology::active_stereo: return "active_stereo";
    case Technology::passive_stereo: return "passive_stereo";
    case Technology::lidar_3d_spinning: return "lidar_3d_spinning";
    case Technology::lidar_2d: return "lidar_2d";
    case Technology::solid_state_lidar: return "solid_state_lidar";
  }
  return "?";
}

std::string to_string(FovShape shape) {
  switch (shape) {
    case FovShape::pyramid: return "pyramid";
    case FovShape::cone: return "cone";
    case FovShape::band: return "band";
    case FovShape::planar: return "planar";
  }
  return "?";
}

std::string to_string(LightCondition condition) {
  switch (condition) {
    case LightCondition::dark: return "dark";
    case LightCondition::indoor: return "indoor";
    case LightCondition::sunlight: return "sunlight";
  }
  return "?";
}

std::string to_string(Basis basis) {
  switch (basis) {
    case Basis::datasheet: return "datasheet";
    case Basis::measured: return "measured";
    case Basis::estimate: return "estimate";
  }
  return "?";
}

}  // namespace rigdesign::model
