#pragma once
// Validators for numeric options: one guard, so no option takes NaN, an infinity or a value
// outside what it means (CLI11's Range lets NaN through: every comparison with NaN is false).
#include <CLI/CLI.hpp>
#include <string>

namespace rigdesign::cli {

/// A finite number in [low, high]; the message names the value and `expected`.
CLI::Validator finite_in(double low, double high, const std::string& expected);

/// A finite number > 0 and <= high.
CLI::Validator positive_up_to(double high, const std::string& expected);

}  // namespace rigdesign::cli
