#pragma once
#include <string>

namespace rigdesign {

/// Shortest readable form of a number for messages: up to `digits` significant digits,
/// no trailing zeros ("3.5", "0.122", "nan").
std::string format_number(double value, int digits = 6);

}  // namespace rigdesign
