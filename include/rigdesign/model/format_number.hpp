#pragma once
#include <string>
#include <vector>

namespace rigdesign::model {

/// Shortest readable form of a number for messages: up to `digits` significant digits,
/// no trailing zeros ("3.5", "0.122", "nan").
std::string format_number(double value, int digits = 6);

/// The shortest text that reads back as exactly `value` ("0.1", "1.5707963267948966"), for
/// files whose numbers must round-trip.
std::string exact_number(double value);
/// The items separated by `separator`, for lists in messages ("a, b, c").
std::string join(const std::vector<std::string>& items, const std::string& separator = ", ");

}  // namespace rigdesign::model
