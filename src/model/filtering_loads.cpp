#include "rigdesign/model/filtering_loads.hpp"

namespace rigdesign::model {

const FilteringLoad* FilteringLoads::find(const std::string& sensor_id) const {
  for (const FilteringLoad& load : sensors) {
    if (load.sensor_id == sensor_id) return &load;
  }
  return nullptr;
}

void FilteringLoads::record(const FilteringLoad& load) {
  for (FilteringLoad& existing : sensors) {
    if (existing.sensor_id == load.sensor_id) {
      if (load.seconds_per_point > existing.seconds_per_point) existing = load;
      return;
    }
  }
  sensors.push_back(load);
}

}  // namespace rigdesign::model
