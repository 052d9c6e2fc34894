#pragma once
#include <string>

#include "rigdesign/model/sensor.hpp"

namespace rigdesign::io {

/// Reads a sensors.yaml library (schema in rigs/README.md). Throws InputError listing every
/// problem found, each with file:line:col, field and the expected form.
model::SensorLibrary load_sensor_library(const std::string& path);

}  // namespace rigdesign::io
