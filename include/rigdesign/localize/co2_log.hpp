#pragma once
/// A robot's CO2 log for gas-source detection (paper 4), in either of two forms:
///   - CSV with a header `t,x,y,z,co2_ppm` (t [s], x y z [m], co2_ppm [ppm]; columns in any
///     order, extra columns ignored), as rigdesign writes it;
///   - whitespace-separated `x y co2_ppm` without header or time, the form of the DARPA SubT
///     Urban trace (shared/data/real/subt_urban/); such a log is untimed.
/// The form is told by the first content line: a comma means CSV. Blank lines and lines
/// starting with '#' are skipped. Errors name file:line:column (1-based character column).
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct Co2Reading {
  double t = 0.0;        ///< [s]; for an untimed log, the reading's index (see Co2Log::timed)
  model::Vec3 position;  ///< [m]; z = 0 in the untimed form
  double ppm = 0;        ///< CO2 concentration [ppm]
};

struct Co2Log {
  std::string source;
  bool timed = true;  ///< false for the `x y co2_ppm` form: t holds the reading's index
  std::vector<Co2Reading> readings;
};

}  // namespace rigdesign::localize
