#pragma once
// What the FOV shape classes share: how many rays fit a span, an angle in degrees, and when an
// angle counts as a pole or a full turn.
#include <string>

namespace rigdesign::model {

/// Angles this close [rad] to a pole (elevation +-90 deg, a cone's axis) or to a full turn are
/// taken as it; datasheet angles converted from degrees land within ~1e-15.
inline constexpr double kFovAngleTolerance = 1e-9;

/// How many steps of `step` [rad] a span [rad] holds, at least one.
int angle_steps(double span, double step);
/// An angle [rad] in degrees with up to 4 significant digits, as the sensor sheet prints it.
std::string degrees_text(double radians);

}  // namespace rigdesign::model
