#pragma once
// `rigdesign localize --calibrate --log FILE... --truth CSV`: paper 4's path-loss model
// calibrated on logs whose emitters' positions are known (the level at 1 m and the exponent by
// least squares), printed with the flags that use it.
#include <ostream>

#include "rigdesign/report/localize_options.hpp"

namespace rigdesign::cli {

int run_calibration(const report::LocalizeOptions& options, std::ostream& out);

}  // namespace rigdesign::cli
