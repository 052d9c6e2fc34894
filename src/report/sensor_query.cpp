#include "rigdesign/report/sensor_query.hpp"

#include <algorithm>
#include <cctype>

#include "rigdesign/model/units.hpp"

namespace rigdesign::report {
namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool mode_matches(const model::SensorMode& mode, const SensorQuery& query) {
  return mode.max_range >= query.min_range && mode.frequency >= query.min_rate &&
         model::rad_to_deg(mode.fov.horizontal()) >= query.min_fov_deg - 1e-9;
}

}  // namespace

std::vector<const model::SensorMode*> matching_modes(const model::Sensor& sensor,
                                                     const SensorQuery& query) {
  std::vector<const model::SensorMode*> modes;
  for (const model::SensorMode& mode : sensor.modes) {
    if (mode_matches(mode, query)) modes.push_back(&mode);
  }
  return modes;
}

bool sensor_matches(const model::Sensor& sensor, const SensorQuery& query) {
  if (!query.technologies.empty() &&
      std::find(query.technologies.begin(), query.technologies.end(),
                model::to_string(sensor.technology)) == query.technologies.end()) {
    return false;
  }
  if (!query.search.empty()) {
    const std::string needle = lowercase(query.search);
    if (lowercase(sensor.id).find(needle) == std::string::npos &&
        lowercase(sensor.name).find(needle) == std::string::npos) {
      return false;
    }
  }
  if (query.max_price > 0 && sensor.price.usd > query.max_price) return false;
  return !matching_modes(sensor, query).empty();
}

}  // namespace rigdesign::report
