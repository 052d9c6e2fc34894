#pragma once
/// Which log a file holds, told from its first content line: an RSSI CSV (header naming
/// `rssi` or `bssid`, so a missing rssi column is reported by the RSSI reader), a CO2 CSV (header
/// naming `co2_ppm`) or the untimed `x y co2_ppm` form.
#include <string>

namespace rigdesign::io {

enum class LogKind { rssi, co2 };

/// Throws InputError (line 1) when the first line is neither form, or the text is empty.
LogKind log_kind_of(const std::string& text, const std::string& file);

/// The file's text; InputError when it cannot be read.
std::string read_log_text(const std::string& path);

}  // namespace rigdesign::io
