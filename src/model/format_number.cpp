#include "rigdesign/model/format_number.hpp"

#include <charconv>
#include <cstdio>

namespace rigdesign::model {

std::string format_number(double value, int digits) {
  if (value == 0.0) value = 0.0;  // -0 (a rotation's rounding, -0.0 * x) reads as a sign error
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::string exact_number(double value) {
  if (value == 0.0) value = 0.0;
  char buffer[64];
  const std::to_chars_result end = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end.ptr);
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string text;
  for (const std::string& item : items) {
    if (!text.empty()) text += separator;
    text += item;
  }
  return text;
}

}  // namespace rigdesign::model
