#pragma once
/// The boundary of a monotone test on an interval, by halving it: the cut depth of a housing,
/// the gap under a floating one, where a ray enters the robot's body.
#include <utility>

namespace rigdesign::geometry {

/// `holds` is false at `low` and true at `high` (and changes once between them). Halves the
/// interval `steps` times, keeping a false end and a true end; returns them {low, high}.
template <typename Test>
std::pair<double, double> bisect(double low, double high, int steps, const Test& holds) {
  for (int step = 0; step < steps; ++step) {
    const double middle = 0.5 * (low + high);
    (holds(middle) ? high : low) = middle;
  }
  return {low, high};
}

}  // namespace rigdesign::geometry
