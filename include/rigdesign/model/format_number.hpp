#pragma once
#include <string>
#include <vector>

namespace rigdesign::model {

/// Shortest readable form of a number for messages: up to `digits` significant digits,
/// no trailing zeros ("3.5", "0.122", "nan").
std::string format_number(double value, int digits = 6);

/// The items separated by `separator`, for lists in messages ("a, b, c").
std::string join(const std::vector<std::string>& items, const std::string& separator = ", ");

}  // namespace rigdesign::model
