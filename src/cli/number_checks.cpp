#include "number_checks.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>

namespace rigdesign::cli {
namespace {

// The whole word as a double, overflow included (1e309 reads as infinity); nullopt when it
// is not a number at all, which CLI11's own conversion then reports.
std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

CLI::Validator make_check(double low, double high, bool low_included, const std::string& expected) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::optional<double> value = parse_number(text);
        if (!value) return {};
        const bool above_low = low_included ? *value >= low : *value > low;
        if (std::isfinite(*value) && above_low && *value <= high) return {};
        return "is " + text + " (expected " + expected + ")";
      },
      expected);
}

}  // namespace

CLI::Validator finite_in(double low, double high, const std::string& expected) {
  return make_check(low, high, true, expected);
}

CLI::Validator positive_up_to(double high, const std::string& expected) {
  return make_check(0.0, high, false, expected);
}

}  // namespace rigdesign::cli
