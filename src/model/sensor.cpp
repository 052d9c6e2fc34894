#include "rigdesign/model/sensor.hpp"

#include <algorithm>
#include <stdexcept>

namespace rigdesign::model {

bool LightImmunity::immune_to(LightCondition condition) const {
  switch (condition) {
    case LightCondition::dark: return dark;
    case LightCondition::indoor: return indoor;
    case LightCondition::sunlight: return sunlight;
  }
  return false;
}

bool Emitter::supports(const std::string& measure) const {
  return std::find(mitigation.begin(), mitigation.end(), measure) != mitigation.end();
}

SensorMode SensorMode::narrowest() const {
  SensorMode narrowed = *this;
  if (!fov_spread) return narrowed;
  const FovShape& shape = fov.shape();
  if (shape.name() == "pyramid") {
    narrowed.fov = FieldOfView(
        pyramid_fov(shape.horizontal() - (*fov_spread)[0], shape.vertical() - (*fov_spread)[1]));
  } else if (shape.name() == "cone") {
    narrowed.fov = FieldOfView(cone_fov(shape.horizontal() - (*fov_spread)[0]));
  }
  return narrowed;
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

const SensorMode& SensorLibrary::resolved_mode(const std::string& sensor_id,
                                               const std::string& mode_id) const {
  const Sensor* sensor = find(sensor_id);
  const SensorMode* mode = sensor ? sensor->find_mode(mode_id) : nullptr;
  if (mode == nullptr)
    throw std::logic_error("unresolved sensor mode " + sensor_id + "/" + mode_id);
  return *mode;
}

std::string to_string(Technology technology) {
  return std::string(name_in(kTechnologyNames, technology));
}

std::string to_string(LightCondition condition) {
  return std::string(name_in(kLightConditionNames, condition));
}

std::string to_string(Basis basis) {
  return std::string(name_in(kBasisNames, basis));
}

}  // namespace rigdesign::model
