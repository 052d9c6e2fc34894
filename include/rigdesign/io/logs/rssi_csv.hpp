#pragma once
/// Reads and writes RSSI logs (CSV; the form is described in rigdesign/localize/rssi_log.hpp).
#include <string>

#include "rigdesign/localize/rssi_log.hpp"

namespace rigdesign::io {

/// Parses the CSV text above; `file` names it in errors. Throws InputError on a missing
/// column, a non-numeric or non-finite number, an RSSI above 0 dBm or a log without readings.
localize::RssiLog parse_rssi_csv(const std::string& text, const std::string& file);

/// Reads and parses a file (InputError when it cannot be opened).
localize::RssiLog read_rssi_log(const std::string& path);

/// The CSV form parse_rssi_csv reads (round trip; numbers with enough digits to reproduce).
std::string to_rssi_csv(const localize::RssiLog& log);

}  // namespace rigdesign::io
