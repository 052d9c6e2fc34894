#include "rigdesign/model/filtering_loads.hpp"

namespace rigdesign::model {

const FilteringLoad* FilteringLoads::find(const std::string& sensor_id) const {
  for (const FilteringLoad& load : sensors) {
    if (load.sensor_id == sensor_id) return &load;
  }
  return nullptr;
}

}  // namespace rigdesign::model
