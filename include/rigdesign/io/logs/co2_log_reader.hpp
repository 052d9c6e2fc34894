#pragma once
/// Reads CO2 logs in both forms described in rigdesign/localize/co2_log.hpp.
#include <string>

#include "rigdesign/localize/co2_log.hpp"

namespace rigdesign::io {

/// Throws InputError on a missing column, a non-numeric field, a negative concentration or a
/// log without readings.
localize::Co2Log parse_co2_log(const std::string& text, const std::string& file);

localize::Co2Log read_co2_log(const std::string& path);

}  // namespace rigdesign::io
