#pragma once
// The library search `rigdesign sensors` and the studio's sensor list share: by technology,
// text, and what one mode must reach at once (range, rate, horizontal FOV), and by price.
#include <string>
#include <vector>

#include "rigdesign/model/sensor.hpp"

namespace rigdesign::report {

struct SensorQuery {
  std::vector<std::string> technologies;  ///< any of these; empty: every technology
  std::string search;                     ///< in the id or name, case-insensitive
  double min_range = 0.0;                 ///< [m]
  double max_price = 0.0;                 ///< [USD] 0: no limit
  double min_rate = 0.0;                  ///< [Hz]
  double min_fov_deg = 0.0;               ///< [deg] horizontal
};

/// The sensor's modes that meet every mode criterion at once: a lidar that reaches 40 m at
/// 10 Hz and 20 m at 20 Hz does not answer "40 m at 20 Hz".
std::vector<const model::SensorMode*> matching_modes(const model::Sensor& sensor,
                                                     const SensorQuery& query);

/// The sensor meets the query: technology, text, price, and one matching mode.
bool sensor_matches(const model::Sensor& sensor, const SensorQuery& query);

}  // namespace rigdesign::report
