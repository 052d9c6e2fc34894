#include "rigdesign/localize/rssi_log.hpp"

namespace rigdesign::localize {

int RssiLog::find(const std::string& bssid) const {
  for (std::size_t i = 0; i < emitters.size(); ++i) {
    if (emitters[i] == bssid) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace rigdesign::localize
