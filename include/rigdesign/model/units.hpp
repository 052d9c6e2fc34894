#pragma once
/// Unit conversions. Code works in SI units (metres, seconds, radians); files may use degrees
/// only in fields whose name ends in `_deg`, converted once at load time.
#include <cmath>
#include <numbers>

namespace rigdesign::model {

constexpr double deg_to_rad(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}
constexpr double rad_to_deg(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

/// `angle` [rad] moved into [0, 2 pi).
inline double wrap_angle(double angle) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  double wrapped = std::fmod(angle, kTwoPi);
  if (wrapped < 0) wrapped += kTwoPi;
  return wrapped >= kTwoPi ? 0.0 : wrapped;  // -1e-17 + 2 pi rounds to 2 pi
}

/// `value` rounded up to a whole number of `unit` (a setting written in centimetres), with a
/// 1e-9 unit's slack so that a value already whole is not pushed up by its rounding error.
inline double round_up(double value, double unit) {
  return std::ceil(value / unit - 1e-9) * unit;
}

}  // namespace rigdesign::model
