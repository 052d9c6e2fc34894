#pragma once
/// Unit conversions. Code works in SI units (metres, seconds, radians); files may use degrees
/// only in fields whose name ends in `_deg`, converted once at load time.
#include <numbers>

namespace rigdesign::model {

constexpr double deg_to_rad(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}
constexpr double rad_to_deg(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

}  // namespace rigdesign::model
