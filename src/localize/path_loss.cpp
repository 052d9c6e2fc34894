#include "rigdesign/localize/path_loss.hpp"

#include <cmath>

namespace rigdesign::localize {

double range_from_rssi(double rssi_dbm, const PathLossParams& params) {
  return std::pow(10.0, (params.rssi_at_1m_dbm - rssi_dbm) / (10.0 * params.exponent));
}

double rssi_at_range(double range, const PathLossParams& params) {
  return params.rssi_at_1m_dbm - 10.0 * params.exponent * std::log10(range);
}

}  // namespace rigdesign::localize
