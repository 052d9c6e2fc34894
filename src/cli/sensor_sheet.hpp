#pragma once
// One sensor of the library in full (`rigdesign sensors ID`): datasheet values, price, sources
// and, per mode, what the metrics derive from them (points and bytes per second, noise at
// range), as text or JSON.
#include <iosfwd>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "rigdesign/model/sensor.hpp"

namespace rigdesign::cli {

void print_sensor_sheet(const model::Sensor& sensor, const model::SensorLibrary& library,
                        std::ostream& out);
nlohmann::json sensor_json(const model::Sensor& sensor, const model::SensorLibrary& library);

}  // namespace rigdesign::cli
