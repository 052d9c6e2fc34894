#include "rigdesign/model/format_number.hpp"

#include <cstdio>

namespace rigdesign {

std::string format_number(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

}  // namespace rigdesign
